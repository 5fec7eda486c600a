#include "ui/training/ExerciseRun.h"

#include "core/config/MachineConfig.h"
#include "core/training/ExerciseMachine.h"

#include <algorithm>

namespace m350::ui {

std::optional<Message> prepareAttemptMachine(const training::Exercise& exercise, const QString& into) {
    return training::prepareExerciseMachine(exercise, config::bundledMachinesDirectory(), into.toStdString());
}

MachineSession::Options attemptSessionOptions(const training::Exercise& exercise, MachineSession::Clock clock) {
    MachineSession::Options options;
    options.clock = clock;
    options.homed = exercise.homed;
    options.tool = exercise.startTool;
    options.panelThread = clock == MachineSession::Clock::Manual;
    for (const training::ToolBreakage& broken : exercise.breaks) {
        options.toolBreaks.push_back({broken.tool, broken.shortBy, broken.at});
    }
    return options;
}

OperatorAction faultAction(const training::InjectedFault& fault, double t) {
    OperatorAction action;
    action.kind = OperatorAction::Kind::Force;
    action.t = t;
    action.force.input = fault.input;
    action.force.fault = QString::fromStdString(fault.fault);
    action.force.level = fault.level;
    action.force.seconds = fault.seconds;
    return action;
}

void injectFaults(const training::Exercise& exercise, std::vector<OperatorAction>& actions, std::vector<ReplayPlace>& places) {
    places.resize(actions.size());
    std::optional<double> firstStart;
    for (const OperatorAction& action : actions) {
        if ((action.kind == OperatorAction::Kind::Key || action.kind == OperatorAction::Kind::KeyDown) &&
            action.name == QLatin1String("START")) {
            firstStart = action.t;
            break;
        }
    }
    for (const training::InjectedFault& fault : exercise.faults) {
        double t = fault.at;
        if (fault.after == training::InjectedFault::After::FirstStart) {
            if (!firstStart) {
                continue; // never started: the fault never comes
            }
            t += *firstStart;
        }
        // after every action of the same moment: the START that triggers it goes first
        auto at = std::upper_bound(actions.begin(), actions.end(), t, [](double time, const OperatorAction& a) { return time < a.t; });
        const auto index = at - actions.begin();
        actions.insert(at, faultAction(fault, t));
        places.insert(places.begin() + index, ReplayPlace{0, 1});
    }
}

} // namespace m350::ui
