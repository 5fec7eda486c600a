#pragma once

class QTableWidget;
class QWidget;

namespace m350::ui {

// A table as the panel's screens show them (ports, parameters, files, log): read-only, whole rows
// selected one at a time, no row numbers, compact rows. It never takes the keyboard focus: UP and
// DOWN reach it through the dispatcher like every other key.
QTableWidget* makePanelTable(QWidget* parent, int columns, const char* objectName, int rowHeight = 22);

} // namespace m350::ui
