#include "core/training/ExerciseTomlReader.h"

#include "core/files/MachineFileRead.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

namespace m350::training {

void ExerciseTomlReader::refuse(const toml::source_region& where, Message words) const {
    ExerciseRefusal refusal;
    refusal.error.place.file = file_;
    refusal.error.place.line = static_cast<int>(where.begin.line);
    refusal.error.place.column = static_cast<int>(where.begin.column);
    refusal.error.words = std::move(words);
    throw refusal;
}

toml::table ExerciseTomlReader::parse() const {
    std::string text;
    if (auto why = files::readMachineFile(file_, text)) {
        refuseFile(message("exercise_unreadable", {bilingual(*why)}));
    }
    try {
        return files::parseTomlText(text, file_);
    } catch (const toml::parse_error& e) {
        refuse(e.source(), message("exercise_bad_toml", {std::string(e.description())}));
    }
}

void ExerciseTomlReader::onlyKeys(const toml::table& table, std::initializer_list<std::string_view> known,
                                  const std::string& in) const {
    for (auto&& [key, value] : table) {
        if (std::find(known.begin(), known.end(), key.str()) == known.end()) {
            std::string list;
            for (std::string_view name : known) {
                list += (list.empty() ? "" : ", ") + std::string(name);
            }
            refuse(key.source(), message("exercise_unknown_key", {std::string(key.str()), in, list}));
        }
    }
}

const toml::node& ExerciseTomlReader::required(const toml::table& table, std::string_view key,
                                               const toml::source_region& where) const {
    const toml::node* node = table.get(key);
    if (!node) {
        refuse(where, message("exercise_missing_key", {std::string(key)}));
    }
    return *node;
}

double ExerciseTomlReader::number(const toml::node& node, std::string_view key) const {
    std::optional<double> value = node.value<double>();
    if (!value || !std::isfinite(*value)) {
        refuse(node.source(), message("exercise_not_a_number", {std::string(key)}));
    }
    return *value;
}

int ExerciseTomlReader::whole(const toml::node& node, std::string_view key, int low, int high) const {
    std::optional<std::int64_t> value = node.value_exact<std::int64_t>();
    if (!value || *value < low || *value > high) {
        refuse(node.source(), message("exercise_not_whole", {std::string(key), std::to_string(low), std::to_string(high)}));
    }
    return static_cast<int>(*value);
}

std::string ExerciseTomlReader::text(const toml::node& node, std::string_view key) const {
    std::optional<std::string> value = node.value_exact<std::string>();
    if (!value) {
        refuse(node.source(), message("exercise_not_text", {std::string(key)}));
    }
    return *value;
}

const toml::table& ExerciseTomlReader::table(const toml::node& node, std::string_view key) const {
    const toml::table* t = node.as_table();
    if (!t) {
        refuse(node.source(), message("exercise_not_table", {std::string(key)}));
    }
    return *t;
}

LocalText ExerciseTomlReader::localText(const toml::node& node, std::string_view key) const {
    const toml::table& t = table(node, key);
    onlyKeys(t, {"zh_CN", "en"}, std::string(key));
    return {text(required(t, "zh_CN", node.source()), std::string(key) + ".zh_CN"),
            text(required(t, "en", node.source()), std::string(key) + ".en")};
}

std::vector<LocalText> ExerciseTomlReader::hints(const toml::node& node) const {
    const toml::table& t = table(node, "hints");
    onlyKeys(t, {"zh_CN", "en"}, "hints");
    const toml::array* zh = required(t, "zh_CN", node.source()).as_array();
    const toml::array* en = required(t, "en", node.source()).as_array();
    if (!zh || !en || zh->size() != en->size()) {
        refuse(node.source(), message("exercise_hints_pair"));
    }
    std::vector<LocalText> out;
    for (std::size_t i = 0; i < zh->size(); ++i) {
        out.push_back({text(*zh->get(i), "hints.zh_CN"), text(*en->get(i), "hints.en")});
    }
    return out;
}

} // namespace m350::training
