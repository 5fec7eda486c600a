#pragma once

// The one way the core includes toml++ (compiled in, header-only: core/CMakeLists.txt), so that
// every file sees it configured alike, and the one way it parses TOML (parseTomlText/File).
//
// toml++ 3.3.0 asserts, in a build without NDEBUG, on a table header that starts with a character
// no key may start with (`[ !]`, `[[[a]]]`), where its own next lines report a parse error (fixed
// upstream in marzer/tomlplusplus#301). With its assertions off every build reports such a file as
// the release build does (FuzzFindingsTest); a release build defines them away itself.
#ifndef TOML_ASSERT
#define TOML_ASSERT(expr) static_cast<void>(0)
#endif
#include <toml++/toml.h>

#include <string>
#include <string_view>

namespace m350::config {

// toml::parse, except that a text holding a code point from U+FB26 to U+FEFE is refused with a
// toml::parse_error at its line and column. toml++ 3.3.0 asks of every character it skips as
// whitespace whether it is Unicode whitespace, and for these code points that test reaches
// __builtin_unreachable (undefined behaviour; UBSan stops there). They are Hebrew and Arabic
// presentation forms, variation selectors and small or vertical punctuation: no machine file needs one.
toml::table parseTomlText(std::string_view text, std::string_view path);

// Reads the file whole and parses it as parseTomlText does; an unreadable file is a toml::parse_error.
toml::table parseTomlFile(const std::string& path);

} // namespace m350::config
