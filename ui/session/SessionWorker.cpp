#include "ui/session/SessionWorker.h"

#include "ui/session/FrameClock.h"

#include "ui/i18n/DiagnosticText.h"
#include "ui/i18n/Language.h"

#include "core/config/HookFiles.h"
#include "core/config/MachineConfig.h"
#include "core/controller/Controller.h"
#include "core/controller/ToolTableSave.h"
#include "core/gcode/Diagnostic.h"
#include "core/params/ParameterNumbers.h"

#include <QDateTime>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace m350::ui {

using controller::Controller;

namespace {

controller::RunSettings settingsFor(const MachineSession::Options& options) {
    controller::RunSettings settings;
    settings.homed = options.homed;
    settings.tool = options.tool;
    settings.toolBreaks = options.toolBreaks;
    settings.externalOutputLimit = options.externalOutputLimit;
    settings.operatorPresent = true; // dialogs and START wait for the operator
    return settings;
}

QString diagnosticsText(const std::vector<gcode::Diagnostic>& diagnostics) {
    QStringList lines;
    for (const gcode::Diagnostic& d : diagnostics) {
        if (d.severity == gcode::Severity::Error && d.kind == gcode::DiagnosticKind::Syntax) {
            lines << DiagnosticText::located(d);
        }
    }
    return lines.join('\n');
}

QString axisNames(const std::vector<int>& axes) {
    static const char* const names[] = {"X", "Y", "Z", "4th", "5th"};
    QStringList out;
    for (int axis : axes) {
        out << QString::fromLatin1(names[axis]);
    }
    return out.join(QLatin1Char(' '));
}

// The breakage monitor's spindle load view: the one shown until a sample came or the tool changed.
std::shared_ptr<const controller::SpindleLoadView> spindleLoadSince(std::shared_ptr<const controller::SpindleLoadView> shown,
                                                                    Controller& controller, int tool) {
    const controller::SpindleLoadWatch& watch = controller.toolBreakage().spindleLoad();
    if (!watch.model() || (shown && shown->taken == watch.monitor().taken() && shown->tool == tool)) {
        return shown;
    }
    return std::make_shared<const controller::SpindleLoadView>(watch.view(tool, controller.dialect().id == gcode::DialectId::Fanuc));
}

} // namespace

SessionWorker::SessionWorker(config::MachineConfig config, MachineSession::Options options)
    : externalOutput_(options.externalOutputLimit),
      beside_(options.clock == MachineSession::Clock::Manual, [this] { publish(); }),
      options_(options) {
    machineName_ = QString::fromStdString(config.name);
    machineNameZh_ = QString::fromStdString(config.nameZh);
    folder_ = config::MachineFolder(config.folder);
    kept_ = config.parameters;
    log_ = std::make_unique<SessionLog>(config.folder);
    controller_ = std::make_unique<Controller>(std::move(config), settingsFor(options));
    controller_->setUserLevel(userLevel_); // the panel starts as a guest
}

SessionWorker::~SessionWorker() = default;

void SessionWorker::begin() {
    if (options_.clock == MachineSession::Clock::RealTime) {
        frames_ = new FrameClock(this);
        frames_->start(options_.rate, [this](double seconds) {
            advance(seconds);
            publish();
        });
    }
    powerOn();
}

void SessionWorker::finish() {
    beside_.finish();
    delete frames_;
    frames_ = nullptr;
    keepExternalOutput(false); // what came within the last second of a run still going
}

void SessionWorker::advanceManual(double seconds) {
    advance(seconds);
    publish();
}

bool SessionWorker::quiet() const {
    return !busy() && activity_ == Activity::None && pendingSteps_.isEmpty() && !beside_.running() &&
           !controller_->manual().jogging();
}

double SessionWorker::advanceWhileQuiet(double seconds, bool publishAtEnd) {
    constexpr double kFrame = 1.0 / 60.0;
    double passed = 0.0;
    while (seconds - passed > 1e-9 && quiet()) {
        const double step = std::min(kFrame, seconds - passed);
        advance(step);
        passed += step;
    }
    if (passed > 0.0 && (publishAtEnd || !quiet())) {
        publish();
    }
    return passed;
}

void SessionWorker::advance(double seconds) {
    sessionTime_ += seconds;
    beside_.advance(seconds);
    const bool wasRunning = busy();
    Controller::RunState state = controller_->advance(seconds);
    noteAlarm();
    if (wasRunning && !busy()) {
        keepParametersTheRunChanged();
    }
    if (state == Controller::RunState::Finished && activity_ == Activity::Auto) {
        // a piece is done: 加工统计 counts it with its run time
        workRecord_.lastPiece = controller_->panelStatus().runSeconds;
        workRecord_.total += workRecord_.lastPiece;
        ++workRecord_.finished;
    }
    if (state != Controller::RunState::Running && state != Controller::RunState::Hold) {
        activity_ = Activity::None;
    }
    continueSteps();
    operatorKeys();
}

void SessionWorker::noteAlarm() {
    const Controller::RunState run = controller_->runState();
    events_.noteAlarm(run == Controller::RunState::Alarm || run == Controller::RunState::EStop,
                      [this] { return controller_->panelStatus().alarm; }, *log_);
}

bool SessionWorker::busy() const {
    auto state = controller_->runState();
    return state == Controller::RunState::Running || state == Controller::RunState::Hold;
}

QString SessionWorker::loadErrors() const { return diagnosticsText(controller_->diagnostics()); }

void SessionWorker::refuse(const QString& why) {
    lastError_ = why;
    publish();
}

void SessionWorker::publish() {
    events_.noteParameterChanges(controller_->takeParameterChanges(), *log_);
    toolData_.keep(controller_->toolTableEdits(), [this] { return controller::saveToolTable(*controller_, folder_); },
                   controller_->toolLife().manager(), folder_);
    keepExternalOutput(busy());
    auto snapshot = std::make_shared<PanelSnapshot>();
    snapshot->status = controller_->panelStatus();
    snapshot->activity = activity_;
    snapshot->sessionTime = sessionTime_;
    snapshot->programFile = programFile_;
    snapshot->mdiLines = mdiLines_;
    snapshot->lastError = lastError_;
    snapshot->machineName = machineName_;
    snapshot->machineNameZh = machineNameZh_;
    snapshot->homingPrompt = controller_->homing().needsBootHomingPrompt() && !busy(); // after sysstart.nc
    snapshot->log = log_->entries();
    snapshot->logProblem = log_->problem();
    snapshot->workRecord = workRecord_;
    snapshot->breakPoints = breakPointFile_.points(controller_->breakRun(), folder_);
    snapshot->toolTable = toolData_.table();
    snapshot->toolTableProblem = toolData_.tableProblem();
    snapshot->toolLife = toolData_.life();
    snapshot->toolLifeProblem = toolData_.lifeProblem();
    snapshot->tWordChangesTool = controller_->dialect().tCodeProgram >= 0;
    spindleLoad_ = spindleLoadSince(std::move(spindleLoad_), *controller_, snapshot->status.tool);
    snapshot->spindleLoad = spindleLoad_;
    if (watchScene_) {
        scene_ = preview::sceneSince(std::move(scene_), *controller_);
        snapshot->scene = scene_;
    }
    snapshot->userLevel = userLevel_;
    if (watchVariables_) {
        snapshot->userVariables = userVariables();
    }
    beside_.fill(*snapshot);
    snapshot->publishedNs = std::chrono::duration_cast<std::chrono::nanoseconds>(
                                std::chrono::steady_clock::now().time_since_epoch())
                                .count();
    emit published(snapshot);
}

void SessionWorker::keepExternalOutput(bool running) {
    if (auto problem = externalOutput_.keep(controller_->externalDevices(), *log_, folder_, running)) {
        lastError_ = *problem;
    }
}

bool SessionWorker::loadCurrentFile() {
    if (fileLoaded_) {
        return true;
    }
    if (!controller_->loadFile(programFile_.toStdString())) {
        refuse(diagnosticsText(controller_->diagnostics()));
        return false;
    }
    fileLoaded_ = true;
    return true;
}

void SessionWorker::start() {
    lastError_.clear();
    if (controller_->runState() == Controller::RunState::Hold) {
        controller_->resume();
        log_->record("resume", programFile_);
    } else if (busy()) {
        return;
    } else if (programFile_.isEmpty()) {
        refuse(tr("No program loaded: load one on the Program page"));
        return;
    } else if (loadCurrentFile()) {
        if (controller_->start()) {
            activity_ = Activity::Auto;
            log_->record("start_work", programFile_);
            workRecord_.file = programFile_;
            if (workRecord_.startedAt.isEmpty()) {
                workRecord_.startedAt = QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
            }
        }
    }
    publish();
}

void SessionWorker::pause() {
    lastError_.clear();
    if (controller_->runState() == Controller::RunState::Running) {
        log_->record("pause", QString::fromStdString(controller_->panelStatus().file));
    }
    controller_->hold();
    keepBreakPoint();
    publish();
}

void SessionWorker::reset() {
    log_->record("reset");
    controller_->reset();
    keepBreakPoint();
    activity_ = Activity::None;
    lastError_.clear();
    publish();
}

void SessionWorker::emergencyStop() {
    lastError_.clear();
    controller_->emergencyStop();
    log_->record("estop");
    noteAlarm();
    activity_ = Activity::None;
    publish();
}

void SessionWorker::loadProgram(const QString& path) {
    if (busy()) {
        refuse(tr("A program is running: wait for it, or PAUSE / RESET first"));
        return;
    }
    programFile_ = path;
    fileLoaded_ = false;
    lastError_.clear();
    if (loadCurrentFile()) {
        beside_.previewLoaded(controller_->config(), path, controller_->panelStatus().tool);
    } else {
        beside_.clearLoaded();
    }
    publish();
}

void SessionWorker::runMdi(const QStringList& lines, Activity activity, bool throughMdiFile) {
    if (busy()) {
        refuse(tr("A program is running: wait for it, or PAUSE / RESET first"));
        return;
    }
    std::vector<std::string> text;
    std::string body;
    for (const QString& line : lines) {
        text.push_back(line.toStdString());
        body += text.back() + "\n";
    }
    lastError_.clear();
    fileLoaded_ = false;
    // The MDI page's line goes into the system disk's mdi.nc, which then runs, as on the M350 (its
    // messages name mdi.nc); a folder that cannot be written runs the line directly.
    const bool viaFile = throughMdiFile && !folder_.path().empty() && !folder_.write(config::FolderFile::MdiProgram, body);
    if (!(viaFile ? controller_->loadHook(config::Hook::Mdi) : controller_->loadMdi(text))) {
        refuse(diagnosticsText(controller_->diagnostics()));
        return;
    }
    if (!viaFile) {
        mdiLines_ = std::make_shared<const QStringList>(lines);
    }
    if (controller_->start()) {
        activity_ = activity;
        log_->record(activity == Activity::Probe ? "probe" : "mdi", lines.join(QStringLiteral("; ")));
    }
    publish();
}

void SessionWorker::answerDialog(bool enter) {
    lastError_.clear();
    controller_->operatorPanel().answerDialog(enter);
    publish();
}

void SessionWorker::setSpindleToolNumber(int tool) {
    lastError_.clear();
    if (!controller_->setSpindleToolNumber(tool)) {
        refuse(tr("Set target tool No.:", "msg 883") + QStringLiteral(" T%1").arg(tool));
        return;
    }
    log_->record("tool_number", QStringLiteral("T%1").arg(tool));
    publish();
}

void SessionWorker::pressExternStart() {
    lastError_.clear();
    controller_->operatorPanel().pressExternStart();
    publish();
}

void SessionWorker::home(const QVector<int>& axes) {
    if (busy()) {
        refuse(tr("A program is running: wait for it, or PAUSE / RESET first"));
        return;
    }
    // the panel's Go Home runs the machine folder's fndzero.nc / fndX.nc (abszero.nc / absX.nc with
    // absolute servos) when it has one
    const bool absolute = controller_->parameter(param::kHomeMode) != 0.0;
    std::optional<config::Hook> hook =
        axes.isEmpty() ? config::goHomeHook(std::nullopt, absolute)
                       : axes.size() == 1 ? config::goHomeHook(axes.front(), absolute) : std::nullopt;
    if (hook && controller_->hasHook(*hook)) {
        runHooks({{*hook, {}, {}}}, Activity::Homing);
        return;
    }
    std::vector<int> which(axes.begin(), axes.end());
    if (which.empty()) {
        which = controller_->homing().homeableAxes();
    }
    lastError_.clear();
    log_->record(axes.isEmpty() ? "home_all" : "home_axis", axisNames(which));
    if (auto alarm = controller_->homing().home(which)) {
        lastError_ = QString::fromStdString(alarm->message);
    }
    publish();
}

void SessionWorker::zeroAxes(const QVector<int>& axes) {
    lastError_.clear();
    if (busy()) {
        refuse(tr("A program is running: wait for it, or PAUSE / RESET first"));
        return;
    }
    for (int axis : axes) {
        controller_->zeroWorkAxis(axis);
    }
    log_->record(axes.size() > 1 ? "zero_all" : "coord_set",
                 axisNames(std::vector<int>(axes.begin(), axes.end())) + QStringLiteral(" = 0"));
    publish();
}

void SessionWorker::setWorkPosition(int axis, double value) {
    lastError_.clear();
    if (busy()) {
        refuse(tr("A program is running: wait for it, or PAUSE / RESET first"));
        return;
    }
    controller_->setWorkPosition(axis, value);
    log_->record("coord_set", axisNames({axis}) + QStringLiteral(" = %1").arg(value, 0, 'f', 3));
    publish();
}

void SessionWorker::setVariable(int number, double value) {
    lastError_.clear();
    Message why;
    if (!controller_->setVariable(number, value, &why)) {
        refuse(QString::fromStdString(why.in(Language::messageLanguage())));
        return;
    }
    publish();
}

void SessionWorker::clearWorkRecord() {
    lastError_.clear();
    controller_->setParameter(param::kTotalRunCount, 0.0);
    controller_->setParameter(param::kPieceCount, 0.0);
    saveParameters({{param::kTotalRunCount, 0.0}, {param::kPieceCount, 0.0}});
    workRecord_ = {};
    log_->record("work_record_cleared");
    publish();
}

void SessionWorker::setParameter(int number, double value) {
    lastError_.clear();
    if (!controller_->setParameter(number, value)) {
        refuse(tr("Parameter %1: invalid value").arg(number));
        return;
    }
    if (!saveParameters({{number, value}})) {
        return;
    }
    publish(); // which logs the change (MachineEventLog)
}

void SessionWorker::startSimulation(const QString& path, double speed) {
    lastError_.clear();
    if (auto error = beside_.start(controller_->config(), path, controller_->panelStatus().tool, speed)) {
        refuse(*error);
        return;
    }
    publish();
}

void SessionWorker::setSimulationSpeed(double speed) {
    beside_.setSpeed(speed);
    publish();
}

void SessionWorker::stopSimulation() {
    beside_.stop();
    publish();
}

} // namespace m350::ui
