#pragma once

#include <string>

namespace m350 {

// The folder of what ships with the programs (machines/, examples/, parameters/): when the running
// program is installed, <prefix>/share/m350-studio found from the executable's own path (so a
// package or a relocated prefix works); else the source tree's resources/ (the build tree, tests).
std::string resourceDirectory();

} // namespace m350
