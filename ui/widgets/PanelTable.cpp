#include "ui/widgets/PanelTable.h"

#include "ui/widgets/MeasuredLabel.h"
#include "ui/widgets/TextSizeDelegate.h"

#include <QHeaderView>
#include <QLabel>
#include <QScrollBar>
#include <QVBoxLayout>

#include <algorithm>

namespace m350::ui {

PanelTable::PanelTable(QWidget* parent, int columns, const char* objectName, int rowHeight)
    : QTableWidget(0, columns, parent), rowHeight_(rowHeight) {
    setObjectName(objectName);
    setFocusPolicy(Qt::NoFocus);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setSelectionMode(QAbstractItemView::SingleSelection);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setVerticalScrollMode(QAbstractItemView::ScrollPerItem); // the scroll bar counts rows
    verticalHeader()->hide();
    verticalHeader()->setDefaultSectionSize(rowHeight);
    new TextSizeDelegate(this);
}

int PanelTable::pageTop(int current, int rows, int pageRows) {
    if (current < 0 || rows <= 0) {
        return 0;
    }
    pageRows = std::max(pageRows, 1);
    return std::min(current / pageRows * pageRows, std::max(rows - pageRows, 0));
}

void PanelTable::scrollTo(const QModelIndex&, ScrollHint) { showCurrentPage(); }

void PanelTable::currentChanged(const QModelIndex& current, const QModelIndex& previous) {
    QTableWidget::currentChanged(current, previous);
    showCurrentPage(); // Qt scrolls a shown table only; a hidden one keeps its page ready too
}

void PanelTable::updateGeometries() {
    QTableWidget::updateGeometries(); // the scroll bar's range for the height the layout gave
    showCurrentPage();
}

void PanelTable::showCurrentPage() {
    const int pageRows = viewport()->height() / rowHeight_;
    verticalScrollBar()->setValue(pageTop(currentRow(), rowCount(), pageRows));
}

QTableWidget* makePanelTable(QWidget* parent, int columns, const char* objectName, int rowHeight) {
    return new PanelTable(parent, columns, objectName, rowHeight);
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
