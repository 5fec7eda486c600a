#pragma once

// The one way the core includes toml++ (compiled in, header-only: core/CMakeLists.txt), so that
// every file sees it configured alike.
//
// toml++ 3.3.0 asserts, in a build without NDEBUG, on a table header that starts with a character
// no key may start with (`[ !]`, `[[[a]]]`), where its own next lines report a parse error (fixed
// upstream in marzer/tomlplusplus#301). With its assertions off every build reports such a file as
// the release build does (FuzzFindingsTest); a release build defines them away itself.
#ifndef TOML_ASSERT
#define TOML_ASSERT(expr) static_cast<void>(0)
#endif
#include <toml++/toml.h>
