#pragma once

#include "core/training/Exercise.h"
#include "ui/actions/OperatorAction.h"
#include "ui/replay/Replay.h"
#include "ui/session/MachineSession.h"

#include <QString>

#include <optional>
#include <vector>

namespace m350::ui {

struct Attempt;

// What an attempt at an exercise starts from, alike in the panel's training mode and the headless
// grader: the machine folder made for it, the session's options, and the exercise's faults among
// the trainee's actions.

// The machine folder for an attempt at `into` (core/training/ExerciseMachine.h), or why not.
std::optional<Message> prepareAttemptMachine(const training::Exercise& exercise, const QString& into);

// The session's options: the exercise's start (homed, the tool in the spindle) and its breaking tools.
MachineSession::Options attemptSessionOptions(const training::Exercise& exercise, MachineSession::Clock clock);

// The exercise's faults as `force` actions at their times (after the attempt's begin, the first
// START key, or the first MDI line run: F1-F6 on the MDI page), put among `actions` in time order; `places` (readReplay's) kept in step, a
// fault's place being line 0.
void injectFaults(const training::Exercise& exercise, std::vector<OperatorAction>& actions, std::vector<ReplayPlace>& places);

// What the grader plays of `attempt`: its actions with the exercise's faults among them, then a time
// mark at the hand-in (time passes to it: a fault or a run still going has its say); `places` in step.
std::vector<OperatorAction> gradedActions(const training::Exercise& exercise, const Attempt& attempt,
                                          std::vector<ReplayPlace>* places);

// A fault as the action that injects it at virtual time `t`.
OperatorAction faultAction(const training::InjectedFault& fault, double t);

} // namespace m350::ui
