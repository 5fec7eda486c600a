#pragma once

#include "core/controller/Controller.h"
#include "core/controller/RunReport.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace m350::sim {

// The `m350-sim` output contract: one JSON object (see README "m350-sim").
nlohmann::json reportJson(const controller::RunReport& report, controller::Controller& controller,
                          const std::vector<int>& printVariables);

// For errors found before anything runs (bad file, bad machine folder).
nlohmann::json errorJson(const std::string& code, const std::string& message, const std::string& file, int line = 0,
                         int column = 0);

nlohmann::json diagnosticsJson(const std::vector<gcode::Diagnostic>& diagnostics);

// JSON text that never throws on a stray byte: invalid UTF-8 is replaced.
std::string dump(const nlohmann::json& j);

} // namespace m350::sim
