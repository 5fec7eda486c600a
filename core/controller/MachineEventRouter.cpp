#include "core/controller/MachineEventRouter.h"

#include "core/controller/MagazineDriver.h"
#include "core/controller/StatusBoard.h"
#include "core/controller/ToolBreakage.h"
#include "core/controller/ToolLifeCounter.h"
#include "core/machine/SimulatedMachine.h"
#include "core/macro/MacroError.h"

#include <cstdio>
#include <string>
#include <utility>

namespace m350::controller {

MachineEventRouter::MachineEventRouter(Context context) : context_(std::move(context)) {}

void MachineEventRouter::onMachineEvent(const machine::MachineEvent& event) {
    if (context_.status.trace()) {
        traceEvent(event);
    }
    if (context_.settings.observer) {
        context_.settings.observer->onMachineEvent(event);
    }
    try {
        if (event.type == machine::MachineEvent::Type::Rapid) {
            checkSetterRapid(event);
        }
        if (context_.magazine.device()) {
            feedMagazine(event);
        }
    } catch (const macro::MacroError& error) {
        // a move that runs into the hardware: where it was going is where it hits (the machine view
        // marks it there; the axes stop where they are when the alarm comes)
        const bool move = event.type == machine::MachineEvent::Type::Rapid ||
                          event.type == machine::MachineEvent::Type::Feed || event.type == machine::MachineEvent::Type::Arc;
        crashPlace_ = error.code == AlarmCode::Crash && move ? std::optional<machine::Axes>(event.to) : std::nullopt;
        throw;
    }
    context_.toolLife.countCuttingTime(event);
    // nothing to sample, nothing that breaks: the common case, every move of a program
    if (context_.breakage.active()) {
        watchSpindleLoad(event);
    }
}

// An input an IoLink drives changes because of the output switch that came before it.
void MachineEventRouter::traceEvent(const machine::MachineEvent& event) {
    TraceSource where = context_.status.source();
    if (event.type == machine::MachineEvent::Type::Io && event.port < 0) {
        if (auto it = inputSource_.find(-event.port); it != inputSource_.end()) {
            where = it->second;
        }
    } else if (event.type == machine::MachineEvent::Type::Io) {
        for (const machine::IoLink& link : context_.config.ioLinks) {
            if (link.output == event.port) {
                inputSource_[link.input] = where;
            }
        }
    }
    context_.status.trace()->machineEvent(event, where);
}

bool MachineEventRouter::ignoresMove(const machine::Axes& from, const machine::Axes& to) const {
    return !context_.status.trace() && !context_.settings.observer && !context_.toolLife.manager().inUse() &&
           !context_.breakage.active() && (!context_.magazine.device() || context_.magazine.ignores(from, to)) &&
           context_.machine.setterPenetration(from, to) <= kSetterContact;
}

// The fixed setter is solid (the M350's 对刀仪, a FANUC's TS27R stylus): a rapid that drives the
// tool below its trip point hits it, as a move into a rack pocket does. Only G31 may meet it.
void MachineEventRouter::checkSetterRapid(const machine::MachineEvent& event) {
    const double depth = context_.machine.setterPenetration(event.from, event.to);
    if (depth <= kSetterContact) {
        return;
    }
    char mm[32];
    std::snprintf(mm, sizeof mm, "%.3f", depth);
    const std::string tool = std::to_string(context_.magazine.spindleTool());
    macro::MacroError crash = macro::MacroError::of(AlarmCode::Crash, message("setter_crash", {tool, mm}));
    if (alarmStands()) {
        context_.status.postMessage(Message{crash.messageId, crash.messageArguments}); // the first alarm stays the one shown
        return;
    }
    throw crash;
}

// The magazine sees every event, also the safe state an alarm drives the outputs to (the drawbar
// clamps, the heads go up): what it holds must follow. Once an alarm stands, what the hardware
// suffers besides is a message, the first alarm stays the one shown.
void MachineEventRouter::feedMagazine(const machine::MachineEvent& event) {
    if (!alarmStands()) {
        context_.magazine.onMachineEvent(event);
        return;
    }
    try {
        context_.magazine.onMachineEvent(event);
    } catch (const macro::MacroError& error) {
        if (error.messageId.empty()) {
            context_.status.postMessage(error.message);
        } else {
            context_.status.postMessage(Message{error.messageId, error.messageArguments});
        }
    }
}

void MachineEventRouter::watchSpindleLoad(const machine::MachineEvent& event) {
    auto anomaly = context_.breakage.sample(event);
    if (anomaly && context_.state == RunState::Running && context_.executor) {
        context_.interruptMotion(anomaly->time); // the axes brake from where they were then
        throw macro::MacroError::of(AlarmCode::SpindleLoad, anomaly->message);
    }
}

} // namespace m350::controller
