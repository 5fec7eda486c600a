#include "core/config/ToolsToml.h"

#include "core/config/TomlReading.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace m350::config {

namespace fs = std::filesystem;

namespace {

using namespace toml_reading;

// [tools.97] length = ..., diameter = ...: one tool beyond the lists (a reference tool).
void readNumberedTools(const fs::path& file, const toml::table& t, MachineConfig& config) {
    const toml::table* tools = t["tools"].as_table();
    for (auto&& [key, value] : tools ? *tools : toml::table{}) {
        const toml::table* tool = value.as_table();
        if (!tool) {
            continue; // the length and diameter lists
        }
        auto index = static_cast<std::size_t>(numberKey(file, key.str(), value.source(), 1, 9999, bilingual("[tools.N] tool", "[tools.N] 刀具")));
        auto set = [&](std::vector<double>& values, const char* name) {
            if (const toml::node* v = tool->get(name)) {
                values.resize(std::max(values.size(), index), 0.0);
                values[index - 1] = std::abs(numberValue(file, *v, name));
            }
        };
        set(config.toolLengths, "length");
        set(config.toolDiameters, "diameter");
    }
}

// [tool_data]: what the control keeps of its tools, which no parameter of ours says.
//   offset_memory = "A" | "C"   FANUC tool compensation memory (a FANUC option; ToolData.h)
//   random_changer = true       LinuxCNC's [EMCIO]RANDOM_TOOLCHANGER = 1: pockets swap on M6
void readToolData(const fs::path& file, const toml::table& t, MachineConfig& config) {
    const toml::table* data = t["tool_data"].as_table();
    if (!data) {
        return;
    }
    if (const toml::node* memory = data->get("offset_memory")) {
        const std::optional<std::string> type = memory->value<std::string>();
        if (!type || (*type != "A" && *type != "C")) {
            fail(file, message("config_offset_memory_choice"), memory->source());
        }
        if (config.dialect->id != gcode::DialectId::Fanuc) {
            fail(file, message("config_offset_memory_fanuc"), memory->source());
        }
        config.offsetMemory = *type == "A" ? tools::OffsetMemory::A : tools::OffsetMemory::C;
    }
    if (const toml::node* random = data->get("random_changer")) {
        const std::optional<bool> on = random->value<bool>();
        if (!on) {
            fail(file, message("config_random_changer_bool"), random->source());
        }
        config.randomToolChanger = *on;
    }
}

} // namespace

void readTools(const fs::path& file, const toml::table& machine, MachineConfig& config) {
    const toml::table& t = machine;
    if (auto lengths = t["tools"]["length"].as_array()) {
        for (const toml::node& length : *lengths) {
            config.toolLengths.push_back(numberValue(file, length, "tools.length"));
        }
    }
    if (auto diameters = t["tools"]["diameter"].as_array()) {
        for (const toml::node& diameter : *diameters) {
            config.toolDiameters.push_back(std::abs(numberValue(file, diameter, "tools.diameter")));
        }
    }
    readNumberedTools(file, t, config);
    readToolData(file, t, config);
}

} // namespace m350::config
