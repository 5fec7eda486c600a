#pragma once

namespace m350::sim {

// m350-sim's exit statuses (README: 0 ok, 1 alarm, 2 error, 64 usage): what a script branches on.
constexpr int kExitOk = 0;
constexpr int kExitAlarm = 1;
constexpr int kExitError = 2; // syntax, a file or a machine folder that cannot be used
constexpr int kExitUsage = 64; // sysexits.h's EX_USAGE

} // namespace m350::sim
