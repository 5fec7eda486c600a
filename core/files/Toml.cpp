#include "core/files/Toml.h"

#include "core/files/MachineFileRead.h"
#include "core/files/TomlScreen.h"

namespace m350::files {

toml::table parseTomlText(std::string_view text, std::string_view path) {
    if (auto refused = findCharacterTomlCannotRead(text)) {
        const toml::source_position at{static_cast<toml::source_index>(refused->line),
                                       static_cast<toml::source_index>(refused->column)};
        throw toml::parse_error(refused->message.c_str(), at, std::make_shared<const std::string>(path));
    }
    return toml::parse(text, path);
}

UnreadableToml::UnreadableToml(Message reason, const std::string& path)
    : toml::parse_error(message("toml_unreadable", {bilingual(reason)}).english().c_str(), toml::source_position{1, 1},
                        std::make_shared<const std::string>(path)),
      reason_(std::move(reason)), why_(message("toml_unreadable", {bilingual(reason_)})) {}

toml::table parseTomlFile(const std::string& path) {
    std::string text;
    if (auto why = readMachineFile(path, text)) {
        throw UnreadableToml(std::move(*why), path);
    }
    return parseTomlText(text, path);
}

} // namespace m350::files
