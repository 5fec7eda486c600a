#pragma once

#include "ui/session/PanelSnapshot.h"

#include <QWidget>

class QLabel;

namespace m350::gcode {
struct Dialect;
}

namespace m350::ui {

class CodeView;
class MachineView;

// 仿真 on the Program page: the file with its running line, the machine view (the compact one of
// 图形显示: the file's whole path, what the simulated run has done of it, the machine), and a line of
// figures (speed, line, simulated time, blocks, points) or the alarm that ended it.
class SimulationPanel : public QWidget {
    Q_OBJECT
public:
    SimulationPanel(const gcode::Dialect& dialect, QWidget* parent = nullptr);
    void open(const QString& path, const QString& text);
    void render(const PanelSnapshot& snapshot);
    CodeView* code() const { return code_; }
    MachineView* view() const { return view_; }
    std::size_t points() const { return points_; } // of the simulated run's path so far
    QString infoText() const;
    static QString speedName(double speed);

private:
    CodeView* code_;
    MachineView* view_;
    std::size_t points_ = 0;
    QLabel* info_;
    QString file_;
};

} // namespace m350::ui
