#pragma once

#include <QTableWidget>
#include <QVector>

class QLabel;
class QVBoxLayout;
class QWidget;

namespace m350::ui {

// A table as the panel's screens show them (ports, parameters, files, log): read-only, whole rows
// selected one at a time, no row numbers, compact rows. It never takes the keyboard focus: UP and
// DOWN reach it through the dispatcher like every other key.
//
// It shows its rows a page at a time, as a CNC panel's lists do: the page of as many whole rows as
// it has room for that holds the current row (the last page ends at the last row). What it shows
// follows from the current row and its height alone, not from the way the cursor came there: the
// live panel, laid out after every key, and a replay, laid out only at its end, show the same rows.
class PanelTable : public QTableWidget {
public:
    PanelTable(QWidget* parent, int columns, const char* objectName, int rowHeight);

    // The first row of the page the table shows now, for `current` (-1: none) of `rows` rows when
    // `pageRows` whole rows fit.
    static int pageTop(int current, int rows, int pageRows);

    // Shows the current row's page (whatever index Qt asks for: the current row is the one shown).
    void scrollTo(const QModelIndex& index, ScrollHint hint = EnsureVisible) override;

protected:
    void currentChanged(const QModelIndex& current, const QModelIndex& previous) override;
    void updateGeometries() override;

private:
    void showCurrentPage();

    int rowHeight_;
};

QTableWidget* makePanelTable(QWidget* parent, int columns, const char* objectName, int rowHeight = 22);

// A table page's parts in a column: labels above (header) and below (info, help), wrapped text, and
// a table whose columns fit their text but the last, which takes the rest of the width.
QLabel* addPanelLabel(QVBoxLayout* column, QWidget* page, const char* objectName, bool wrap);
QTableWidget* addPanelTable(QVBoxLayout* column, QWidget* page, int columns, const char* objectName);

// While it lives, a table being filled does not measure its fitted columns again at each item set:
// Qt measured every row each time, so filling the System Log's 500 rows took 250,000 text
// measurements (seconds). The columns are measured once, from the same text, when it goes.
class TableFill {
public:
    explicit TableFill(QTableWidget* table);
    ~TableFill();
    TableFill(const TableFill&) = delete;
    TableFill& operator=(const TableFill&) = delete;

private:
    QTableWidget* table_;
    QVector<int> fitted_;
};

} // namespace m350::ui
