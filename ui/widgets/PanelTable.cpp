#include "ui/widgets/PanelTable.h"

#include "ui/widgets/MeasuredLabel.h"
#include "ui/widgets/TextSizeDelegate.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace m350::ui {

QTableWidget* makePanelTable(QWidget* parent, int columns, const char* objectName, int rowHeight) {
    auto* table = new QTableWidget(0, columns, parent);
    table->setObjectName(objectName);
    table->setFocusPolicy(Qt::NoFocus);
    table->setSelectionBehavior(QAbstractItemView::SelectRows);
    table->setSelectionMode(QAbstractItemView::SingleSelection);
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->verticalHeader()->hide();
    table->verticalHeader()->setDefaultSectionSize(rowHeight);
    new TextSizeDelegate(table);
    return table;
}

QLabel* addPanelLabel(QVBoxLayout* column, QWidget* page, const char* objectName, bool wrap) {
    auto* label = new MeasuredLabel(page);
    label->setObjectName(objectName);
    label->setWordWrap(wrap);
    column->addWidget(label);
    return label;
}

QTableWidget* addPanelTable(QVBoxLayout* column, QWidget* page, int columns, const char* objectName) {
    QTableWidget* table = makePanelTable(page, columns, objectName);
    for (int c = 0; c < columns - 1; ++c) {
        table->horizontalHeader()->setSectionResizeMode(c, QHeaderView::ResizeToContents);
    }
    table->horizontalHeader()->setSectionResizeMode(columns - 1, QHeaderView::Stretch);
    column->addWidget(table, 1);
    return table;
}

TableFill::TableFill(QTableWidget* table) : table_(table) {
    QHeaderView* header = table_->horizontalHeader();
    for (int c = 0; c < header->count(); ++c) {
        if (header->sectionResizeMode(c) == QHeaderView::ResizeToContents) {
            fitted_.push_back(c);
            header->setSectionResizeMode(c, QHeaderView::Fixed);
        }
    }
}

TableFill::~TableFill() {
    for (int c : fitted_) {
        table_->horizontalHeader()->setSectionResizeMode(c, QHeaderView::ResizeToContents);
    }
}

} // namespace m350::ui
