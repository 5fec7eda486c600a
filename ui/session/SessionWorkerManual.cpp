// The operator's manual controls, run in the machine's thread: jog keys, the handwheel and 试切,
// the override and spindle keys, the IO page's output switches and the trainer's input faults.
#include "ui/session/SessionWorker.h"

#include "ui/session/HookSteps.h"

#include "core/controller/Controller.h"

namespace m350::ui {

using controller::Controller;

void SessionWorker::jogPress(int axis, int direction) {
    lastError_.clear();
    controller_->manual().jogPress(axis, direction);
    publish();
}

void SessionWorker::jogRelease(int axis) {
    lastError_.clear();
    controller_->manual().jogRelease(axis);
    publish();
}

void SessionWorker::cycleJogMode() {
    lastError_.clear();
    using Mode = controller::JogMode;
    switch (controller_->manual().jogMode()) {
    case Mode::Continuous: controller_->manual().setJogMode(Mode::Step); break;
    case Mode::Step: controller_->manual().setJogMode(Mode::Mpg); break;
    case Mode::Mpg: controller_->manual().setJogMode(Mode::Continuous); break;
    }
    publish();
}

void SessionWorker::setJogStep(double distance) {
    lastError_.clear();
    controller_->manual().setJogStep(distance);
    publish();
}

void SessionWorker::toggleJogHighSpeed() {
    lastError_.clear();
    jogHigh_ = !jogHigh_;
    controller_->manual().setJogHighSpeed(jogHigh_);
    publish();
}

void SessionWorker::wheel(int axis, int multiplier, int detents, double seconds) {
    lastError_.clear();
    controller_->manual().wheelTurn(axis, multiplier, detents, seconds);
    publish();
}

void SessionWorker::toggleHandwheelGuide() {
    lastError_.clear();
    controller_->manual().setHandwheelGuide(!controller_->manual().handwheelGuide());
    publish();
}

void SessionWorker::setGuideRetrace(bool retrace) {
    lastError_.clear();
    controller_->manual().setGuideReverse(retrace ? controller::GuideReverse::Retrace : controller::GuideReverse::Hold);
    publish();
}

// The override keys: 0 back to 100 %, else a step of `step` percent.
void SessionWorker::feedOverrideKey(int step) {
    lastError_.clear();
    feedOverride_ = controller_->setFeedOverride(step == 0 ? 100.0 : feedOverride_ + step);
    publish();
}

void SessionWorker::spindleOverrideKey(int step) {
    lastError_.clear();
    spindleOverride_ = controller_->manual().setSpindleOverride(step == 0 ? 100.0 : spindleOverride_ + step);
    publish();
}

// The panel's M-code keys run their hook file (M3.nc ...) when the machine folder has one, else
// the M code as an MDI line. SPINDLE is M3 or M5.
void SessionWorker::spindleKey(int code) {
    if (code == 0) {
        bool turning = controller_->status().spindleDisplay() != machine::SpindleState::Stop;
        code = turning ? 5 : 3;
    }
    if (auto step = mCodeKeyStep(code)) {
        runHooks({*step}, Activity::SpindleKey);
    } else {
        runMdi({QStringLiteral("M%1").arg(code)}, Activity::SpindleKey);
    }
}

void SessionWorker::setOutput(int port, int level) {
    lastError_.clear();
    if (!controller_->manual().setOutputByOperator(port, level)) {
        refuse(tr("A program is running: wait for it, or PAUSE / RESET first"));
        return;
    }
    log_->record("output", QStringLiteral("OUT%1 = %2").arg(port, 2, 10, QLatin1Char('0')).arg(level));
    publish();
}

void SessionWorker::forceInput(int pin, MachineSession::Fault fault, int level, double seconds) {
    lastError_.clear();
    if (pin < 1 || pin > machine::kInputCount) {
        refuse(tr("IN%1: no such input (IN01-IN24)").arg(pin));
        return;
    }
    std::optional<machine::InputFault> put;
    switch (fault) {
    case MachineSession::Fault::None: break;
    case MachineSession::Fault::Stuck: put = machine::InputFault::stuck(level); break;
    case MachineSession::Fault::Slow: put = machine::InputFault::delayed(seconds); break;
    case MachineSession::Fault::Bouncing: put = machine::InputFault::bouncing(seconds); break;
    case MachineSession::Fault::Pressed:
        controller_->pressInput(pin, level, seconds);
        publish();
        return;
    }
    controller_->setInputFault(pin, put);
    publish();
}

} // namespace m350::ui
