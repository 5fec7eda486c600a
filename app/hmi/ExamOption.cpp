#include "app/hmi/ExamOption.h"

#include "ui/i18n/Language.h"

#include <variant>

namespace m350::hmi {

std::optional<std::string> readExamOption(const std::string& file, const ui::Language& language, training::Exam* exam) {
    auto loaded = training::loadExam(file);
    if (auto* error = std::get_if<training::ExerciseError>(&loaded)) {
        return error->where() + ": " + error->words.in(language.spoken());
    }
    *exam = std::get<training::Exam>(loaded);
    return std::nullopt;
}

} // namespace m350::hmi
