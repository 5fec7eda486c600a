#pragma once

#include <cstdint>

namespace m350::controller {

// The CONT-STEP-MPG key's three modes: 连续 (moves while the key is held), 寸动 (one step per
// press), 手轮 (the handwheel moves the axis).
enum class JogMode : std::uint8_t { Continuous, Step, Mpg };

// What turning the wheel backwards does in the handwheel guide (试切): Hold stops the program;
// Retrace runs the path already made backwards. Whether the M350 retraces is not confirmed, so
// the trainer offers both; Retrace is the default.
enum class GuideReverse : std::uint8_t { Hold, Retrace };

} // namespace m350::controller
