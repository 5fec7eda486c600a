#pragma once

namespace m350::controller {

// Where the loaded program's run stands (Controller::runState()).
enum class RunState { Idle, Running, Hold, Finished, Alarm, EStop };

} // namespace m350::controller
