#include "ui/pages/PanelTable.h"

#include <QHeaderView>
#include <QTableWidget>

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
    return table;
}

} // namespace m350::ui
