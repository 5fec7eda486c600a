#include "ui/session/SimulationRun.h"

#include "ui/i18n/AlarmText.h"
#include "ui/i18n/DiagnosticText.h"

#include "core/config/MachineConfig.h"
#include "core/controller/Controller.h"
#include "core/gcode/Diagnostic.h"
#include "core/machine/ArcGeometry.h"

#include <QElapsedTimer>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace m350::ui {

using controller::Controller;

namespace {

constexpr double kChord = 0.5;   // mm: the longest chord an arc is drawn with
constexpr int kMaxChords = 256;  // per arc, however large

} // namespace

std::unique_ptr<SimulationRun> SimulationRun::start(const config::MachineConfig& config, const QString& path,
                                                    std::optional<int> tool, double speed, QString* error) {
    std::unique_ptr<SimulationRun> run(new SimulationRun);
    controller::RunSettings settings;
    settings.homed = true;
    settings.tool = tool;
    settings.observer = run.get();
    run->controller_ = std::make_unique<Controller>(config, settings);
    if (!run->controller_->loadFile(path.toStdString())) {
        QStringList lines;
        for (const gcode::Diagnostic& d : run->controller_->diagnostics()) {
            if (d.severity == gcode::Severity::Error && d.kind == gcode::DiagnosticKind::Syntax) {
                lines << DiagnosticText::located(d);
            }
        }
        *error = lines.join('\n');
        return nullptr;
    }
    run->view_.file = path;
    run->view_.speed = speed;
    run->view_.run = SimulationView::Run::Running;
    if (!run->controller_->start()) {
        run->view_.run = SimulationView::Run::Alarm;
    }
    run->follow();
    return run;
}

SimulationRun::~SimulationRun() = default;

void SimulationRun::advance(double seconds) {
    if (!running()) {
        return;
    }
    controller_->advance(seconds);
    follow();
}

void SimulationRun::runFor(long long wallNs) {
    QElapsedTimer wall;
    wall.start();
    while (running() && wall.nsecsElapsed() < wallNs) {
        controller_->advance(1.0);
        follow();
    }
}

// The run's state after a step; a program stop is the operator's START away.
void SimulationRun::follow() {
    switch (controller_->runState()) {
    case Controller::RunState::Hold: controller_->resume(); break;
    case Controller::RunState::Finished: view_.run = SimulationView::Run::Finished; break;
    case Controller::RunState::Alarm:
    case Controller::RunState::EStop: {
        view_.run = SimulationView::Run::Alarm;
        controller::PanelStatus status = controller_->panelStatus();
        if (status.alarm) {
            view_.alarm = AlarmText::located(*status.alarm);
        }
        break;
    }
    case Controller::RunState::Idle:
    case Controller::RunState::Running: break;
    }
}

void SimulationRun::onMachineEvent(const machine::MachineEvent& event) {
    using Type = machine::MachineEvent::Type;
    if (event.type != Type::Rapid && event.type != Type::Feed && event.type != Type::Arc) {
        return;
    }
    if (!started_) {
        started_ = true;
        add(event.from, true);
    }
    if (event.arc) {
        const machine::Arc& arc = *event.arc;
        int chords = std::clamp(static_cast<int>(std::ceil(arc.length / kChord)), 2, kMaxChords);
        for (int i = 1; i < chords; ++i) {
            add(arc.pointAt(arc.length * i / chords), false);
        }
    }
    add(event.to, event.type == Type::Rapid);
}

void SimulationRun::add(const machine::Axes& at, bool rapid) {
    tail_.push_back({static_cast<float>(at(0)), static_cast<float>(at(1)), static_cast<float>(at(2)), rapid});
    ++view_.path.size;
    if (tail_.size() == SimulationPath::kChunk) {
        view_.path.chunks.push_back(std::make_shared<const std::vector<PathPoint>>(std::move(tail_)));
        tail_ = {};
        tail_.reserve(SimulationPath::kChunk);
    }
}

SimulationView SimulationRun::view() {
    controller::PanelStatus status = controller_->panelStatus();
    view_.runningFile = QString::fromStdString(status.file);
    view_.line = status.line;
    view_.time = status.runSeconds;
    view_.blocks = status.blocks;
    view_.moves = status.runMoves;
    view_.scene = preview::sceneSince(std::move(view_.scene), *controller_);
    SimulationView out = view_;
    if (!tail_.empty()) {
        out.path.chunks.push_back(std::make_shared<const std::vector<PathPoint>>(tail_));
    }
    return out;
}

} // namespace m350::ui
