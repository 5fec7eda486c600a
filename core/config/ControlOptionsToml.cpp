#include "core/config/ControlOptionsToml.h"

#include "core/config/TomlReading.h"

#include <charconv>

namespace m350::config {

namespace {

using toml_reading::fail;

// "100-499" (or one number, "98000"), as FANUC's manuals write a range of variables; a leading #
// is allowed on each end.
std::optional<macro::VariableRange> parseRange(std::string_view text) {
    auto number = [](std::string_view part) -> std::optional<int> {
        if (!part.empty() && part.front() == '#') {
            part.remove_prefix(1);
        }
        int value = 0;
        auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
        if (ec != std::errc() || end != part.data() + part.size() || part.empty()) {
            return std::nullopt;
        }
        return value;
    };
    const std::size_t dash = text.find('-');
    auto first = number(text.substr(0, dash));
    auto last = dash == std::string_view::npos ? first : number(text.substr(dash + 1));
    if (!first || !last) {
        return std::nullopt;
    }
    return macro::VariableRange{*first, *last};
}

void readCommonVariables(const std::filesystem::path& file, const toml::node& node, MachineConfig& config) {
    if (config.dialect->id != gcode::DialectId::Fanuc) {
        fail(file, message("config_common_fanuc_only"), node.source());
    }
    const toml::array* list = node.as_array();
    if (!list || list->empty()) {
        fail(file, message("config_common_list"), node.source());
    }
    std::vector<macro::VariableRange> ranges;
    for (const toml::node& entry : *list) {
        auto text = entry.value<std::string>();
        auto range = text ? parseRange(*text) : std::nullopt;
        if (!range) {
            fail(file, message("config_common_range_string"), entry.source());
        }
        ranges.push_back(*range);
        if (auto refused = macro::VariableLayout::refusedCommon(ranges)) {
            fail(file, message("config_common_refused", {bilingual(*refused)}), entry.source());
        }
    }
    config.variableLayout.common = std::move(ranges);
}

void readCoordinates(const std::filesystem::path& file, const toml::table& coordinates, MachineConfig& config) {
    if (config.dialect->id != gcode::DialectId::Fanuc) {
        fail(file, message("config_coordinates_fanuc_only"), coordinates.source());
    }
    config.variableLayout.additionalWorkSystems = toml_reading::wholeValue(
        file, coordinates, "additional_systems", 0, macro::VariableLayout::kMostWorkSystems, -1);
    if (const toml::node* rotation = coordinates.get("rotation")) {
        auto on = rotation->value_exact<bool>();
        if (!on) {
            fail(file, message("config_rotation_bool"), rotation->source());
        }
        config.coordinateRotation = *on;
    }
}

} // namespace

void readControlOptions(const std::filesystem::path& file, const toml::table& machine, MachineConfig& config) {
    if (const toml::node* common = machine["variables"]["common"].node()) {
        readCommonVariables(file, *common, config);
    }
    if (const toml::node* coordinates = machine.get("coordinates")) {
        const toml::table* table = coordinates->as_table();
        if (!table) {
            fail(file, message("config_coordinates_table"), coordinates->source());
        }
        readCoordinates(file, *table, config);
    }
}

} // namespace m350::config
