#pragma once

#include <QString>

namespace m350::hmi {

constexpr int kExitError = 2;  // an input or an output m350-hmi cannot use
constexpr int kExitUsage = 64; // sysexits.h's EX_USAGE, as m350-sim

// Says `message` on stderr as m350-hmi's own ("m350-hmi: ...") and returns `status` for main.
int refuse(const QString& message, int status = kExitError);

} // namespace m350::hmi
