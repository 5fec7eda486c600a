#include "ui/training/ExerciseRun.h"

#include "core/config/MachineConfig.h"
#include "core/training/ExerciseMachine.h"
#include "ui/actions/PanelKey.h"
#include "ui/pages/PageId.h"
#include "ui/training/AttemptFile.h"

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

namespace {

bool isKey(const OperatorAction& action) {
    return action.kind == OperatorAction::Kind::Key || action.kind == OperatorAction::Kind::KeyDown;
}

std::optional<double> firstStart(const std::vector<OperatorAction>& actions) {
    for (const OperatorAction& action : actions) {
        if (isKey(action) && action.name == QLatin1String("START")) {
            return action.t;
        }
    }
    return std::nullopt;
}

// F1-F6 pressed on the MDI page (opened by its key or a page action, left by another page's) runs
// an MDI line: the moment a change typed in MDI begins, whenever the trainee gets there.
std::optional<double> firstMdiRun(const std::vector<OperatorAction>& actions) {
    bool onMdi = false;
    for (const OperatorAction& action : actions) {
        if (isKey(action)) {
            const PanelKey* key = PanelKey::named(action.name);
            if (key && key->role == PanelKey::Role::Page) {
                onMdi = key->page == PageId::mdi;
            }
        } else if (action.kind == OperatorAction::Kind::Page) {
            onMdi = action.name == PageId::mdi;
        } else if (action.kind == OperatorAction::Kind::Softkey && onMdi && action.softkey <= 6) {
            return action.t;
        }
    }
    return std::nullopt;
}

} // namespace

void injectFaults(const training::Exercise& exercise, std::vector<OperatorAction>& actions, std::vector<ReplayPlace>& places) {
    places.resize(actions.size());
    const std::optional<double> started = firstStart(actions);
    const std::optional<double> mdiRun = firstMdiRun(actions);
    for (const training::InjectedFault& fault : exercise.faults) {
        double t = fault.at;
        using After = training::InjectedFault::After;
        if (fault.after != After::Begin) {
            const std::optional<double>& from = fault.after == After::FirstStart ? started : mdiRun;
            if (!from) {
                continue; // never started: the fault never comes
            }
            t += *from;
        }
        // after every action of the same moment: the START that triggers it goes first
        auto at = std::upper_bound(actions.begin(), actions.end(), t, [](double time, const OperatorAction& a) { return time < a.t; });
        const auto index = at - actions.begin();
        actions.insert(at, faultAction(fault, t));
        places.insert(places.begin() + index, ReplayPlace{0, 1});
    }
}

std::vector<OperatorAction> gradedActions(const training::Exercise& exercise, const Attempt& attempt,
                                          std::vector<ReplayPlace>* places) {
    std::vector<OperatorAction> actions = attempt.actions;
    *places = attempt.places;
    injectFaults(exercise, actions, *places);
    const double end = attempt.timeUsed();
    if (actions.empty() || actions.back().t < end) {
        OperatorAction handIn;
        handIn.t = end;
        actions.push_back(handIn);
        places->push_back({0, 1});
    }
    return actions;
}

} // namespace m350::ui
