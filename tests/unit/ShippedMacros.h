#pragma once

// The bundled machines' macro libraries as text, for training scenarios that run them with one
// line made wrong: the program file carries the changed copy, which wins over the machine's own.

#include "core/config/MachineConfig.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

namespace m350::test {

// A bundled machine's library file, whole.
inline std::string shippedLibrary(const std::string& machine, const std::string& file = "slib-g.nc") {
    std::ifstream in(config::bundledMachinesDirectory() + "/" + machine + "/" + file);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_FALSE(text.str().empty()) << machine << "/" << file;
    return text.str();
}

// `text` with `right` replaced by `wrong` (which must be there once at least).
inline std::string withLine(std::string text, const std::string& right, const std::string& wrong) {
    std::size_t at = text.find(right);
    EXPECT_NE(at, std::string::npos) << right;
    if (at != std::string::npos) {
        text.replace(at, right.size(), wrong);
    }
    return text;
}

// The 1-based line of `program` on which `text` first stands.
inline std::uint32_t lineOf(const std::string& program, const std::string& text) {
    std::size_t at = program.find(text);
    EXPECT_NE(at, std::string::npos) << text;
    return static_cast<std::uint32_t>(std::count(program.begin(), program.begin() + static_cast<long>(at), '\n') + 1);
}

} // namespace m350::test
