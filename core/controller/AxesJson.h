#pragma once

#include "core/machine/MachineTypes.h"

#include <nlohmann/json.hpp>

#include <string>

namespace m350::controller {

// {"X": .., "Y": .., "Z": .., "A": .., "B": ..}, as the trace and the m350-sim report write positions.
inline nlohmann::json axesJson(const machine::Axes& a) {
    nlohmann::json j = nlohmann::json::object();
    for (int i = 0; i < machine::kAxisCount; ++i) {
        j[std::string(1, machine::kAxisNames[static_cast<std::size_t>(i)])] = a(i);
    }
    return j;
}

} // namespace m350::controller
