#include "core/config/VariablesToml.h"

#include "core/config/MachineFolder.h"
#include "core/config/TomlReading.h"
#include "core/macro/VariableMap.h"

#include <string>

namespace m350::config {

namespace fs = std::filesystem;

namespace {

using namespace toml_reading;

} // namespace

void loadVariables(const fs::path& folder, MachineConfig& config) {
    fs::path file = folder / MachineFolder::fileName(FolderFile::Variables);
    if (!fs::exists(file)) {
        return;
    }
    toml::table t = parseToml(file);
    warnUnknownKeys(file, t, {"variables", "variables.*"}, config);
    const macro::VariableMap map(*config.dialect, config.variableLayout);
    if (auto vars = t["variables"].as_table()) {
        for (auto&& [key, value] : *vars) {
            const int number = numberKey(file, key.str(), key.source(), 1, macro::VariableLayout::kLastVariable,
                                         bilingual("variable", "变量"));
            const double v = numberValue(file, value, key.str());
            if (map.describe(number).kind == macro::VariableKind::Undefined) {
                config.warn(warningAt(file, key.source(), message("config_variable_undefined", {std::to_string(number)})));
                continue;
            }
            config.variables[number] = v;
        }
    }
}

} // namespace m350::config
