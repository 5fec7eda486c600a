#pragma once

namespace m350::controller {

// Where a run stands (Controller::runState()): the parts that refuse an edit while a program runs
// or holds read it through a const reference to the controller's.
enum class RunState { Idle, Running, Hold, Finished, Alarm, EStop };

// A program runs or holds: the tool table, the tool life and the outputs are its own until RESET.
inline bool programActive(RunState state) { return state == RunState::Running || state == RunState::Hold; }

} // namespace m350::controller
