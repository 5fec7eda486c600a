#pragma once

#include "core/training/Exercise.h"

#include <optional>
#include <string>

namespace m350::training {

// Makes the machine folder an attempt starts from at `into` (a new folder): a copy of the bundled
// machine with the exercise's changes (parameters into params.toml, the changed lines, the
// exercise's own files). The bundled folder is never written. Why not, when it cannot.
std::optional<Message> prepareExerciseMachine(const Exercise& exercise, const std::string& machinesFolder,
                                              const std::string& into);

} // namespace m350::training
