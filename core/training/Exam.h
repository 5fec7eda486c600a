#pragma once

#include "core/training/Exercise.h"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace m350::training {

// An exam the trainer sets (exam.toml): the exercises in order, one time limit for each (or each
// exercise's own), and the key every attempt's hash chain is made with. Hints are off.
struct Exam {
    std::vector<std::string> exercises;
    std::optional<double> timeLimit;
    std::string key;
};

std::variant<Exam, ExerciseError> loadExam(const std::string& file);

} // namespace m350::training
