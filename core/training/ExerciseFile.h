#pragma once

#include "core/training/Exercise.h"

#include <string>
#include <variant>

namespace m350::training {

// The exercise folder's file.
inline constexpr const char* kExerciseFileName = "exercise.toml";

// Reads `folder`/exercise.toml: every key known, every check complete, the machine bundled, every
// file it names present; else why not at file:line:col. `machinesFolder`: where the bundled machine
// folders are (config::bundledMachinesDirectory()).
std::variant<Exercise, ExerciseError> loadExercise(const std::string& folder, const std::string& machinesFolder);

// The exercises under `folder` (resources/exercises), by folder name; one that does not load is
// listed with its error.
struct ExerciseListing {
    std::vector<Exercise> exercises;
    std::vector<ExerciseError> errors;
};
ExerciseListing loadExercises(const std::string& folder, const std::string& machinesFolder);

// The bundled exercises: resourceDirectory()/exercises.
std::string bundledExercisesDirectory();

} // namespace m350::training
