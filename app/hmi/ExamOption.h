#pragma once

#include "core/training/Exam.h"

#include <optional>
#include <string>

namespace m350::ui {
class Language;
}

namespace m350::hmi {

// --exam FILE read (exam.toml); why it is refused, at file:line:col in the panel's language.
std::optional<std::string> readExamOption(const std::string& file, const ui::Language& language, training::Exam* exam);

} // namespace m350::hmi
