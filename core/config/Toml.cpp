#include "core/config/Toml.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace m350::config {

namespace fs = std::filesystem;

namespace {

// Far above any real machine file; /dev/zero or a huge file named as one is refused, not read.
constexpr std::uintmax_t kMostTomlBytes = 16 * 1024 * 1024;

// In UTF-8 every code point from U+F000 to U+FFFF is EF followed by two continuation bytes.
constexpr char32_t kFirstUnclassified = 0xFB26;
constexpr char32_t kLastUnclassified = 0xFEFE;

bool isContinuation(unsigned char byte) { return (byte & 0xC0) == 0x80; }

void refuseUnclassified(std::string_view text, std::string_view path) {
    toml::source_position at{1, 1};
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (byte == '\n') {
            ++at.line;
            at.column = 1;
            continue;
        }
        if (isContinuation(byte)) {
            continue; // a code point is counted once, at its lead byte
        }
        if (byte == 0xEF && i + 2 < text.size() && isContinuation(static_cast<unsigned char>(text[i + 1])) &&
            isContinuation(static_cast<unsigned char>(text[i + 2]))) {
            const char32_t code = 0xF000 | ((static_cast<unsigned char>(text[i + 1]) & 0x3F) << 6) |
                                  (static_cast<unsigned char>(text[i + 2]) & 0x3F);
            if (code >= kFirstUnclassified && code <= kLastUnclassified) {
                char name[16];
                std::snprintf(name, sizeof name, "U+%04X", static_cast<unsigned>(code));
                const std::string message = std::string("character ") + name +
                                            " is not accepted in a machine file (U+FB26 to U+FEFE: presentation "
                                            "forms, variation selectors, small and vertical punctuation)";
                throw toml::parse_error(message.c_str(), at, std::make_shared<const std::string>(path));
            }
        }
        ++at.column;
    }
}

} // namespace

toml::table parseTomlText(std::string_view text, std::string_view path) {
    refuseUnclassified(text, path);
    return toml::parse(text, path);
}

toml::table parseTomlFile(const std::string& path) {
    const auto unreadable = [&path](const std::string& why) {
        return toml::parse_error(("cannot read: " + why).c_str(), toml::source_position{1, 1},
                                 std::make_shared<const std::string>(path));
    };
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        throw unreadable(ec ? ec.message() : "not a regular file (a folder, FIFO or device)");
    }
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec || size > kMostTomlBytes) {
        throw unreadable(ec ? ec.message()
                            : std::to_string(size) + " bytes is more than a machine file can be (16 MiB)");
    }
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in || in.bad()) {
        throw unreadable("the file could not be read");
    }
    return parseTomlText(text.str(), path);
}

} // namespace m350::config
