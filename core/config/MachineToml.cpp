#include "core/config/MachineToml.h"

#include "core/common/Numeric.h"
#include "core/config/ControlOptionsToml.h"
#include "core/config/InterfaceSignals.h"
#include "core/config/LibrariesToml.h"
#include "core/config/MachineFolder.h"
#include "core/config/MagazineToml.h"
#include "core/config/SpindleLoadToml.h"
#include "core/config/TomlReading.h"
#include "core/config/ToolsToml.h"
#include "core/params/ParameterLimits.h"

#include <cmath>
#include <string>

namespace m350::config {

namespace fs = std::filesystem;

namespace {

using namespace toml_reading;

} // namespace

void loadMachineToml(const fs::path& folder, MachineConfig& config) {
    fs::path file = folder / MachineFolder::fileName(FolderFile::Machine);
    if (!fs::exists(file)) {
        fail(file, message("config_no_machine_toml"));
    }
    toml::table t = parseToml(file);
    if (t.empty()) {
        config.warn(warningIn(file, message("config_machine_toml_empty")));
    }
    warnUnknownKeys(file, t,
                    {"name", "name_zh", "dialect", "libraries", "libraries.g", "libraries.m", "libraries.other", "codes", "codes.*",
                     "io_links", "io_links.output", "io_links.input", "io_links.delay_ms", "io_links.inverted",
                     "magazine", "magazine.device", "magazine.capacity", "magazine.loading", "magazine.opening",
                     "magazine.carried", "magazine.forks", "magazine.station", "magazine.slide_travel", "magazine.fork_depth", "magazine.tolerance",
                     "magazine.seconds_per_pocket", "magazine.settle_s", "magazine.clamp_ms",
                     "magazine.in_position_input", "magazine.select_outputs", "magazine.strobe_output",
                     "magazine.pockets", "magazine.slide_s", "magazine.slide_output", "magazine.at_spindle_input",
                     "magazine.away_input", "magazine.drawbar_output", "magazine.released_input",
                     "magazine.clamped_input", "magazine.change_xy", "homing", "homing.switch_distance",
                     "tool_setter", "tool_setter.top", "tool_setter.radius", "floating_setter", "floating_setter.top",
                     "tools", "tools.*", // tools.length, tools.diameter, [tools.N]
                     "stock", "stock.top", "stock.x", "stock.y", "spindle_load",
                     "spindle_load.idle", "spindle_load.per_krpm", "spindle_load.per_cm3", "spindle_load.spike_factor",
                     "spindle_load.spike_ms", "reference_points", "reference_points.*", "tool_data",
                     "tool_data.offset_memory", "tool_data.random_changer", "interface_signals",
                     "interface_signals.*", "variables", "variables.common", "coordinates",
                     "coordinates.additional_systems", "coordinates.rotation"},
                    config);
    config.name = t["name"].value_or(folder.filename().string());
    config.nameZh = t["name_zh"].value_or(std::string());
    std::string dialect = t["dialect"].value_or(std::string("m350"));
    config.dialect = gcode::Dialect::byName(dialect);
    if (!config.dialect) {
        fail(file, message("config_unknown_dialect", {dialect}));
    }
    readLibraries(folder, file, t, config);
    if (auto codes = t["codes"].as_table()) {
        for (auto&& [key, value] : *codes) {
            std::string_view k = key.str();
            if (k.size() < 2 || (k[0] != 'M' && k[0] != 'G')) {
                fail(file, message("config_codes_key", {std::string(k)}));
            }
            int code = numberKey(file, k.substr(1), key.source(), 0, 9999, bilingual("code", "代码"));
            const int program = roundToInt(numberValue(file, value, k));
            const std::string origin = "[codes] " + std::string(k) + " = " + std::to_string(program) + " (" +
                                       settingPlace(file, key.source()) + ")";
            if (config.codeCalls.add(k[0], code, {program, macro::CallKind::Subprogram, 0, origin})) {
                fail(file, message("config_codes_twice", {std::string(1, k[0]) + std::to_string(code)}), key.source());
            }
        }
    }
    if (auto links = t["io_links"].as_array()) {
        for (const toml::node& node : *links) {
            const toml::table* link = node.as_table();
            if (!link) {
                fail(file, message("config_io_links_tables"));
            }
            machine::IoLink l;
            l.output = (*link)["output"].value_or(0);
            l.input = (*link)["input"].value_or(0);
            l.delay = (*link)["delay_ms"].value_or(150.0) / 1000.0;
            l.inverted = (*link)["inverted"].value_or(false);
            if (l.output < 1 || l.output > machine::kOutputCount || l.input < 1 || l.input > machine::kInputCount) {
                fail(file, message("config_io_link_pins"));
            }
            config.ioLinks.push_back(l);
        }
    }
    if (const toml::table* magazine = t["magazine"].as_table()) {
        config.magazineCapacity = wholeValue(file, *magazine, "capacity", 0, params::kMostPockets, 0);
    }
    if (const toml::table* magazine = t["magazine"].as_table(); magazine && magazine->contains("device")) {
        if (auto wrong = readMagazine(*magazine, config.magazine)) {
            fail(file, *wrong);
        }
    }
    if (auto distances = t["homing"]["switch_distance"].as_array()) {
        if (distances->size() > 5) {
            fail(file, message("config_switch_distance_axes"));
        }
        for (std::size_t i = 0; i < distances->size(); ++i) {
            config.homeSwitchDistance[i] = std::abs(numberValue(file, *distances->get(i), "switch_distance"));
        }
    }
    config.setterTop = t["tool_setter"]["top"].value_or(config.setterTop);
    config.setterRadius = t["tool_setter"]["radius"].value_or(config.setterRadius);
    if (auto top = t["floating_setter"]["top"].value<double>()) {
        config.floatingSetterTop = *top;
    }
    readTools(file, t, config);
    readSpindleLoadWorld(file, t, config.spindleLoad);
    if (config.dialect->id == gcode::DialectId::Fanuc) {
        readInterfaceSignals(file, t, config.interfaceSignals);
    } else if (const toml::node* signals = t.get("interface_signals")) {
        config.warn(warningAt(file, signals->source(), message("config_interface_signals_m350")));
    }
    readControlOptions(file, t, config);
    if (auto points = t["reference_points"].as_table()) {
        for (auto&& [key, value] : *points) {
            int number = numberKey(file, key.str(), key.source(), 1, 4, bilingual("reference point", "参考点"));
            const toml::array* axes = value.as_array();
            if (!axes || axes->size() > 5) {
                fail(file, message("config_reference_point_axes", {std::to_string(number)}));
            }
            std::array<double, 5> position{};
            for (std::size_t i = 0; i < axes->size(); ++i) {
                position[i] = numberValue(file, *axes->get(i), key.str());
            }
            config.referencePoints[number] = position;
        }
    }
}

} // namespace m350::config
