#include "ui/program/SimulationPanel.h"

#include "ui/program/CodeView.h"
#include "ui/i18n/AlarmText.h"
#include "ui/view/MachineView.h"
#include "ui/widgets/WrappedLabel.h"

#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace m350::ui {

SimulationPanel::SimulationPanel(const gcode::Dialect& dialect, QWidget* parent) : QWidget(parent) {
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    auto* row = new QHBoxLayout;
    code_ = new CodeView(dialect, this);
    code_->setObjectName("simulationCode");
    code_->setReadOnly(true);
    view_ = new MachineView(this);
    view_->setObjectName("simulationView");
    row->addWidget(code_, 2);
    row->addWidget(view_, 3);
    info_ = new WrappedLabel(this);
    info_->setObjectName("simulationInfo");
    column->addLayout(row, 1);
    column->addWidget(info_);
}

void SimulationPanel::open(const QString& path, const QString& text) {
    file_ = path;
    code_->setProgram(text);
    view_->setContent({});
    points_ = 0;
    info_->clear();
}

QString SimulationPanel::speedName(double speed) {
    return speed > 0.0 ? QStringLiteral("x%1").arg(speed) : tr("Max");
}

void SimulationPanel::render(const PanelSnapshot& snapshot) {
    const SimulationView& view = snapshot.simulation;
    const bool here = QFileInfo(view.runningFile).fileName() == QFileInfo(file_).fileName();
    code_->setRunningLine(view.run == SimulationView::Run::Running && here ? static_cast<int>(view.line) : 0);
    MachineViewContent content;
    content.preview = snapshot.simulationPreview;
    content.scene = view.scene ? view.scene : snapshot.scene; // the simulated machine, as its run leaves it
    if (view.path.size > 0) {
        const auto& last = view.path.chunks.back()->back();
        content.nose = preview::ScenePoint{last.x, last.y, last.z};
    }
    if (view.moves > 0) {
        const bool under = view.run == SimulationView::Run::Running;
        content.done = static_cast<std::size_t>(under ? view.moves - 1 : view.moves);
        if (under) {
            content.current = content.done;
        }
    }
    if (view.run == SimulationView::Run::Alarm) {
        content.alarm = view.alarm;
    }
    view_->setContent(std::move(content));
    points_ = view.path.size;
    QString state = view.run == SimulationView::Run::Finished ? tr("SL over", "msg 125")
                    : view.run == SimulationView::Run::Alarm  ? view.alarm
                                                              : tr("Start Simulating", "msg 111");
    info_->setText(tr("%1  speed %2  line %3  %4 s  %5 blocks  %6 points")
                       .arg(state, speedName(view.speed))
                       .arg(view.line)
                       .arg(view.time, 0, 'f', 1)
                       .arg(static_cast<qulonglong>(view.blocks))
                       .arg(static_cast<qulonglong>(view.path.size)));
}

QString SimulationPanel::infoText() const { return info_->text(); }

} // namespace m350::ui
