// What the panel shows: the controller's state copied into a PanelStatus at the display time.
#include "core/controller/Controller.h"

#include "core/common/Numeric.h"
#include "core/params/AxisSetup.h"
#include "core/params/ParameterNumbers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace m350::controller {


namespace {

PanelStatus::Run runOf(Controller::RunState state) {
    switch (state) {
    case Controller::RunState::Idle: return PanelStatus::Run::Idle;
    case Controller::RunState::Running: return PanelStatus::Run::Running;
    case Controller::RunState::Hold: return PanelStatus::Run::Hold;
    case Controller::RunState::Finished: return PanelStatus::Run::Finished;
    case Controller::RunState::Alarm: return PanelStatus::Run::Alarm;
    case Controller::RunState::EStop: return PanelStatus::Run::EStop;
    }
    return PanelStatus::Run::Idle;
}

} // namespace

PanelStatus Controller::panelStatus() {
    PanelStatus out;
    out.run = runOf(state_);
    out.time = displayTime_;
    out.machine = displayPosition();
    // the offsets in force, applied to where the axes are at the display time
    out.work = out.machine - (machine_.position() - interp_.workPosition());
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        out.homed[static_cast<std::size_t>(axis)] = homing_.homed(axis);
    }
    static_assert(params::AxisSetup::kAxes == machine::kAxisCount);
    const params::AxisSetup axes = params::axisSetup(config_.parameters);
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        const auto i = static_cast<std::size_t>(axis);
        out.axisShown[i] = axes.present(axis);
        out.axisName[i] = axes.names[i];
        out.axisRotary[i] = axes.rotary[i];
    }
    out.workSystem = interp_.activeSlot();
    for (int slot = 0; slot < interp::WorkOffsets::kSlots; ++slot) {
        out.workOffsets[static_cast<std::size_t>(slot)] = offsets_.slot(slot);
    }
    out.feedOverride = feedOverride_;
    out.spindleOverride = manual_.state().spindleOverride;
    out.jogOverride = manual_.state().jogOverride;
    out.jogMode = manual_.state().mode;
    out.jogStep = manual_.state().step;
    out.jogHighSpeed = manual_.state().highSpeed;
    out.jogging = manual_.jogging();
    out.guide = manual_.state().guide;
    out.guideDirection = manual_.state().guide ? manual_.state().override.direction() : 0;
    out.guideOverride = manual_.state().guide ? std::abs(manual_.state().override.value()) * 100.0 : 0.0;
    out.feed = interp_.state().feed;
    out.spindle = status_.spindleDisplay();
    // SRO scales what the spindle turns at, up to its maximum (param 82)
    out.spindleRpm = machine_.spindleTurning() ? std::min(machine_.spindleRpm() * manual_.state().spindleOverride / 100.0,
                                                          machine_.limits().maxSpindleRpm)
                                               : 0.0;
    out.tool = spindleTool();
    if (toolGuard_.doubt().doubt()) {
        out.toolUnsure = toolGuard_.doubt().notice();
    }
    out.totalCount = saturatingInt(config_.parameters.get(param::kTotalRunCount));
    out.pieceCount = saturatingInt(config_.parameters.get(param::kPieceCount));
    out.runSeconds = state_ == RunState::Idle ? 0.0 : std::max(0.0, displayTime_ - runStartedAt_);
    out.modalLine = status_.modalLine();
    out.message = status_.statusLine();
    out.notice = status_.notice();
    out.programStop = programStop_.text();
    if (auto dialog = panel_.pendingDialog()) {
        out.dialog = dialog->text;
    }
    out.alarm = alarm_;
    if (alarm_ && alarm_->code == AlarmCode::Crash && machineEvents_.crashPlace()) {
        out.alarmPlace = *machineEvents_.crashPlace();
    }
    if (executor_) {
        if (auto loc = executor_->location()) {
            out.file = program_.fileName(*loc);
            out.line = loc->line;
        }
        out.blocks = executor_->blocksExecuted();
    }
    out.runMoves = machine_.movesMade() - runMovesFrom_;
    out.mdi = mdi_;
    if (auto wait = panel_.sensorWait()) {
        out.sensorWait = PanelStatus::SensorWait{wait->input, wait->awaitedLevel, wait->seconds, wait->file, wait->line};
    }
    for (int port = 1; port <= machine::kInputCount; ++port) {
        out.inputs[static_cast<std::size_t>(port - 1)] = machine_.input(port);
    }
    for (int port = 1; port <= machine::kOutputCount; ++port) {
        out.outputs[static_cast<std::size_t>(port - 1)] = machine_.output(port);
    }
    out.parameters = config_.parameters;
    return out;
}

} // namespace m350::controller
