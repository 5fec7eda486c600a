#include "core/files/Toml.h"

#include "core/files/TomlScreen.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace m350::files {

namespace fs = std::filesystem;

namespace {

// Far above any real machine file; /dev/zero or a huge file named as one is refused, not read.
constexpr std::uintmax_t kMostTomlBytes = 16 * 1024 * 1024;

} // namespace

toml::table parseTomlText(std::string_view text, std::string_view path) {
    if (auto refused = findCharacterTomlCannotRead(text)) {
        const toml::source_position at{static_cast<toml::source_index>(refused->line),
                                       static_cast<toml::source_index>(refused->column)};
        throw toml::parse_error(refused->message.c_str(), at, std::make_shared<const std::string>(path));
    }
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
    if (!in) {
        throw unreadable("the file could not be read");
    }
    return parseTomlText(text.str(), path);
}

} // namespace m350::files
