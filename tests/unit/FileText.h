#pragma once

// Whole files as text, for the tests of what the machine folder's writers leave on disk.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace m350::test {

inline std::string readText(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

inline void writeText(const std::filesystem::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
}

} // namespace m350::test
