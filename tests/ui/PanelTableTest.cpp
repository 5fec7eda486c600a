// The panel's lists show a page at a time (PanelTable): the page of whole rows that holds the
// current row, the last page ending at the last row, whatever way the cursor came there and
// whenever the table was laid out; a replay that lays the panel out only at its end shows the
// same rows as the live panel.
#include "tests/ui/PanelHarness.h"
#include "ui/widgets/PanelTable.h"

#include <QHeaderView>
#include <QScrollBar>

namespace m350::test {

namespace {

// The Param page's table with the macro variables #50-#499 (F5): 450 rows.
ui::PanelTable* variableTable(PanelHarness& panel) {
    panel.page(QStringLiteral("param"));
    panel.softkey(5);
    QCoreApplication::processEvents();
    return panel.window().findChild<ui::PanelTable*>(QStringLiteral("paramTable"));
}

int wholeRows(ui::PanelTable* table) { return table->viewport()->height() / table->verticalHeader()->defaultSectionSize(); }

void keys(PanelHarness& panel, const char* name, int times) {
    for (int i = 0; i < times; ++i) {
        panel.key(QLatin1String(name));
    }
}

} // namespace

TEST(PanelTable, APageHoldsTheCurrentRowAndTheLastPageEndsAtTheLastRow) {
    using ui::PanelTable;
    EXPECT_EQ(PanelTable::pageTop(0, 100, 10), 0);
    EXPECT_EQ(PanelTable::pageTop(9, 100, 10), 0);
    EXPECT_EQ(PanelTable::pageTop(10, 100, 10), 10);
    EXPECT_EQ(PanelTable::pageTop(57, 100, 10), 50);
    EXPECT_EQ(PanelTable::pageTop(95, 97, 10), 87); // the last page: the last ten rows
    EXPECT_EQ(PanelTable::pageTop(3, 5, 10), 0);    // fewer rows than a page
    EXPECT_EQ(PanelTable::pageTop(-1, 50, 10), 0);  // no current row
    EXPECT_EQ(PanelTable::pageTop(7, 50, 0), 7);    // no room: the current row alone
}

TEST(PanelTable, TheVariableListTurnsItsPagesAsTheCursorLeavesThem) {
    PanelHarness panel;
    ui::PanelTable* table = variableTable(panel);
    ASSERT_NE(table, nullptr);
    const int page = wholeRows(table);
    ASSERT_GT(page, 3);
    ASSERT_GT(table->rowCount(), 3 * page);

    keys(panel, "DOWN", page - 1); // the last row of the first page: nothing scrolls
    EXPECT_EQ(table->currentRow(), page - 1);
    EXPECT_EQ(table->verticalScrollBar()->value(), 0);
    keys(panel, "DOWN", 1); // past it: the second page, the cursor on its first row
    EXPECT_EQ(table->verticalScrollBar()->value(), page);
    keys(panel, "DOWN", page + 2);
    EXPECT_EQ(table->currentRow(), 2 * page + 2);
    EXPECT_EQ(table->verticalScrollBar()->value(), 2 * page);
    keys(panel, "UP", 3); // back over the page's top: the page before, whole
    EXPECT_EQ(table->currentRow(), 2 * page - 1);
    EXPECT_EQ(table->verticalScrollBar()->value(), page);
}

TEST(PanelTable, AListMovedWhileItsPageWasNotShownShowsTheCurrentRowsPageWhenItComesBack) {
    PanelHarness panel;
    ui::PanelTable* table = variableTable(panel);
    ASSERT_NE(table, nullptr);
    const int page = wholeRows(table);
    panel.page(QStringLiteral("monitor"));
    ASSERT_TRUE(table->isHidden() || !table->isVisible());
    // the cursor moved while the table is hidden (a page's own reset, a replay's held switch)
    table->selectRow(3 * page + 1);
    panel.page(QStringLiteral("param"));
    QCoreApplication::processEvents();
    EXPECT_EQ(table->verticalScrollBar()->value(), 3 * page);
}

} // namespace m350::test
