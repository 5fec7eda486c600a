#pragma once

#include "core/training/Exercise.h"
#include "core/training/ExerciseTomlReader.h"

#include <filesystem>

namespace m350::training {

// One [[checks]] entry of exercise.toml: its kind's keys and no others; a file_line check's file
// must be one of `machineFolder`'s.
Check readCheck(const ExerciseTomlReader& in, const toml::table& t, const toml::source_region& where,
                const std::filesystem::path& machineFolder);

} // namespace m350::training
