#include "core/training/Exam.h"

#include "core/files/MachineFileRead.h"
#include "core/files/Toml.h"

#include <cmath>

namespace m350::training {

namespace {

ExerciseError examError(const std::string& file, const toml::source_region& where, Message words) {
    ExerciseError error;
    error.place.file = file;
    error.place.line = static_cast<int>(where.begin.line);
    error.place.column = static_cast<int>(where.begin.column);
    error.words = std::move(words);
    return error;
}

} // namespace

std::variant<Exam, ExerciseError> loadExam(const std::string& file) {
    std::string text;
    if (auto why = files::readMachineFile(file, text)) {
        return examError(file, {}, message("exercise_unreadable", {bilingual(*why)}));
    }
    toml::table root;
    try {
        root = files::parseTomlText(text, file);
    } catch (const toml::parse_error& e) {
        return examError(file, e.source(), message("exercise_bad_toml", {std::string(e.description())}));
    }
    Exam exam;
    for (auto&& [key, value] : root) {
        if (key.str() != "exercises" && key.str() != "time_limit" && key.str() != "key") {
            return examError(file, key.source(), message("exercise_unknown_key", {std::string(key.str()), "exam", "exercises, time_limit, key"}));
        }
    }
    const toml::array* list = root["exercises"].as_array();
    if (!list || list->empty()) {
        return examError(file, root.source(), message("exam_no_exercises"));
    }
    for (const toml::node& name : *list) {
        std::optional<std::string> value = name.value_exact<std::string>();
        if (!value || value->empty()) {
            return examError(file, name.source(), message("exercise_not_text", {"exercises"}));
        }
        exam.exercises.push_back(*value);
    }
    if (const toml::node* limit = root.get("time_limit")) {
        std::optional<double> seconds = limit->value<double>();
        if (!seconds || !std::isfinite(*seconds) || *seconds <= 0.0) {
            return examError(file, limit->source(), message("exercise_time_limit"));
        }
        exam.timeLimit = *seconds;
    }
    if (const toml::node* key = root.get("key")) {
        std::optional<std::string> value = key->value_exact<std::string>();
        if (!value) {
            return examError(file, key->source(), message("exercise_not_text", {"key"}));
        }
        exam.key = *value;
    }
    return exam;
}

} // namespace m350::training
