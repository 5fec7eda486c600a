#pragma once

#include <algorithm>
#include <cmath>

namespace m350::devices {

// A disc or carousel of `pockets` turning the shortest way from pocket `from` to `to`: the pockets
// it passes, + toward higher numbers (a half turn goes that way).
inline int shortestTurn(int from, int to, int pockets) {
    const int forward = ((to - from) % pockets + pockets) % pockets;
    return forward <= pockets - forward ? forward : forward - pockets;
}

// Which pocket faces the station at virtual time `now` when a turn of `steps` pockets from pocket
// `from` began at `started` at `secondsPerPocket`: fractional on the way, counted from 1 up to
// pockets + 1 (past the last pocket comes the first); `from + steps` once the travel is done.
inline double turnPosition(int from, int steps, int pockets, double started, double secondsPerPocket, double now) {
    const double seconds = std::abs(steps) * secondsPerPocket;
    const double done = seconds > 0.0 ? std::clamp((now - started) / seconds, 0.0, 1.0) : 1.0;
    const double at = from - 1 + steps * done;
    return std::fmod(std::fmod(at, pockets) + pockets, pockets) + 1.0;
}

} // namespace m350::devices
