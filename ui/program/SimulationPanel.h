#pragma once

#include "ui/session/SimulationView.h"

#include <QWidget>

class QLabel;

namespace m350::gcode {
struct Dialect;
}

namespace m350::ui {

class CodeView;
class PathView;

// 仿真 on the Program page: the file with its running line, the path drawn as it grows, and a
// line of figures (speed, line, simulated time, blocks, points) or the alarm that ended it.
class SimulationPanel : public QWidget {
    Q_OBJECT
public:
    SimulationPanel(const gcode::Dialect& dialect, QWidget* parent = nullptr);
    void open(const QString& path, const QString& text);
    void render(const SimulationView& view);
    CodeView* code() const { return code_; }
    PathView* path() const { return path_; }
    QString infoText() const;
    static QString speedName(double speed);

private:
    CodeView* code_;
    PathView* path_;
    QLabel* info_;
    QString file_;
};

} // namespace m350::ui
