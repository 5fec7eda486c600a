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

#include "core/common/Message.h"

#include <string>
#include <string_view>

namespace m350::files {

// toml::parse, except that a text toml++ 3.3.0 cannot read without undefined behaviour (see
// TomlScreen.h) is refused with a toml::parse_error at the character that it stumbles on.
toml::table parseTomlText(std::string_view text, std::string_view path);

// A file parseTomlFile could not read at all (a FIFO, a folder, too big, what the OS said): a
// toml::parse_error at 1:1 whose description is the English, with the reason by message id for
// a reader that says it in its language.
class UnreadableToml : public toml::parse_error {
public:
    UnreadableToml(Message reason, const std::string& path);
    const Message& why() const { return why_; }       // "cannot read: it is a FIFO ..."
    const Message& reason() const { return reason_; } // "it is a FIFO ..."

private:
    Message reason_;
    Message why_;
};

// Reads the file whole and parses it as parseTomlText does; an unreadable file is an UnreadableToml.
toml::table parseTomlFile(const std::string& path);

} // namespace m350::files
