#include "core/config/MachineConfig.h"
#include "core/tools/ToolLifeFile.h"
#include "core/common/Numeric.h"
#include "core/common/ResourceDirectory.h"

#include "core/params/FanucParameters.h"
#include "core/config/CallCodeParameters.h"
#include "core/config/ControlOptionsToml.h"
#include "core/config/HookFiles.h"
#include "core/config/MachineFolder.h"
#include "core/files/LastGoodCopy.h"
#include "core/files/MachineFileRead.h"
#include "core/config/MagazineToml.h"
#include "core/params/ParameterCatalogue.h"
#include "core/params/ParameterLimits.h"
#include "core/config/TomlReading.h"
#include "core/macro/VariableMap.h"
#include "core/config/SpindleLoadToml.h"
#include "core/tools/ToolData.h"
#include "core/tools/ToolTableFile.h"
#include "core/tools/ToolTableText.h"

#include "core/files/Toml.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>

namespace m350::config {

namespace fs = std::filesystem;

namespace {

using namespace toml_reading;

// "file:line:col", where a setting stands, for messages that name it.
std::string placeOf(const fs::path& file, const toml::source_region& where) {
    return file.string() + ":" + std::to_string(where.begin.line) + ":" + std::to_string(where.begin.column);
}

// "file: warning: the lines above were not read (its last good copy: ...)"
Message linesNotRead(const fs::path& file) {
    return warningIn(file, message("config_lines_not_read", {files::lastGoodPath(file).string()}));
}

// slibuser.nc, the user's G-code handlers (O9100-O9199 = G100-G199), is loaded beside slib-g.nc
// as the M350 does, whether or not machine.toml lists it.
void addUserLibrary(const fs::path& folder, MachineConfig& config) {
    auto path = hookPath(folder.string(), Hook::UserLibrary);
    if (!path) {
        return;
    }
    std::error_code ec;
    for (const LibraryFile& library : config.libraries) {
        if (fs::equivalent(library.path, *path, ec)) {
            return;
        }
    }
    config.libraries.push_back({*path, gcode::FileRole::GLibrary});
}

bool isInside(const fs::path& path, const fs::path& folder) {
    std::error_code ec;
    const fs::path real = fs::weakly_canonical(path, ec);
    const fs::path within = ec ? fs::path() : fs::weakly_canonical(folder, ec);
    if (ec || real.empty() || within.empty()) {
        return false;
    }
    const fs::path relative = real.lexically_relative(within);
    return !relative.empty() && *relative.begin() != "..";
}

// Where a library may lie once `..` and every symlink are resolved: the machine folder, the
// bundled machine folders (the program's own, which share slib-g.nc and slib-probe.nc), and the
// folder the user names in M350_LIBRARIES. A copied folder must not make the simulator read (and
// echo in its messages) any other file of this computer.
std::vector<fs::path> libraryFolders(const fs::path& folder) {
    std::vector<fs::path> folders{folder, bundledMachinesDirectory()};
    if (const char* named = std::getenv(kLibrariesVariable); named && *named) {
        folders.emplace_back(named);
    }
    return folders;
}

// A program file (.nc) of a machine folder beside this one (`../m350-linear16/slib-m.nc` in a copy
// of the bundled machines): its folder holds a machine.toml and shares this folder's parent.
bool inSiblingMachineFolder(const fs::path& path, const fs::path& folder) {
    std::error_code ec;
    const fs::path real = fs::weakly_canonical(path, ec);
    const fs::path self = ec ? fs::path() : fs::weakly_canonical(folder, ec);
    if (ec || real.empty() || self.empty()) {
        return false;
    }
    std::string extension = real.extension().string();
    for (char& c : extension) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    const fs::path sibling = real.parent_path();
    return extension == ".nc" && sibling.parent_path() == self.parent_path() &&
           fs::is_regular_file(sibling / "machine.toml", ec);
}

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
    auto addLibrary = [&](const toml::node& node, gcode::FileRole role) {
        auto name = node.value<std::string>();
        if (!name) {
            fail(file, message("config_library_not_name"), node.source());
        }
        fs::path path = folder / *name;
        const std::vector<fs::path> allowed = libraryFolders(folder);
        if (std::none_of(allowed.begin(), allowed.end(), [&](const fs::path& f) { return isInside(path, f); }) &&
            !inSiblingMachineFolder(path, folder)) {
            fail(file, message("config_library_outside", {*name, folder.string(), kLibrariesVariable}), node.source());
        }
        std::error_code ec;
        const fs::file_status status = fs::status(path, ec);
        if (!fs::exists(status)) {
            fail(file, message("config_library_missing", {*name, folder.string()}), node.source());
        }
        if (!fs::is_regular_file(status)) {
            fail(file, message("config_library_not_file", {*name}), node.source());
        }
        config.libraries.push_back({path.string(), role});
    };
    if (auto libs = t["libraries"].as_table()) {
        if (auto g = libs->get("g")) {
            addLibrary(*g, gcode::FileRole::GLibrary);
        }
        if (auto m = libs->get("m")) {
            addLibrary(*m, gcode::FileRole::MLibrary);
        }
        if (auto other = libs->get_as<toml::array>("other")) {
            for (const toml::node& n : *other) {
                addLibrary(n, gcode::FileRole::Library);
            }
        }
    }
    addUserLibrary(folder, config);
    if (auto codes = t["codes"].as_table()) {
        for (auto&& [key, value] : *codes) {
            std::string_view k = key.str();
            if (k.size() < 2 || (k[0] != 'M' && k[0] != 'G')) {
                fail(file, message("config_codes_key", {std::string(k)}));
            }
            int code = numberKey(file, k.substr(1), key.source(), 0, 9999, bilingual("code", "代码"));
            const int program = roundToInt(numberValue(file, value, k));
            const std::string origin = "[codes] " + std::string(k) + " = " + std::to_string(program) + " (" +
                                       placeOf(file, key.source()) + ")";
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

void loadParams(const fs::path& folder, MachineConfig& config) {
    fs::path file = folder / MachineFolder::fileName(FolderFile::Params);
    const auto* known = std::get_if<params::ParameterCatalogue>(&params::ParameterCatalogue::bundled());
    // On an M350 a parameter params.toml does not set has its factory value (the catalogue's
    // default, the firmware's default_setting), as after 恢复出厂设置; the uncatalogued ones (IO
    // enables and levels) stay 0. A FANUC control has none of the M350's factory values: there an
    // absent one stays 0, as before.
    if (known && config.dialect->id != gcode::DialectId::Fanuc) {
        known->applyDefaults(config.parameters);
    }
    if (!fs::exists(file)) {
        rebuildCallCodes(config); // [codes] alone: nothing to clash with
        return;
    }
    toml::table t = parseToml(file);
    warnUnknownKeys(file, t, {"params", "params.*"}, config);
    if (auto params = t["params"].as_table()) {
        for (auto&& [key, value] : *params) {
            const bool fanuc = config.dialect->id == gcode::DialectId::Fanuc;
            int n = numberKey(file, key.str(), key.source(), 0,
                              fanuc ? params::kLastFanucParameter : params::ParameterTable::kCount - 1,
                              bilingual("parameter", "参数"));
            double v = numberValue(file, value, key.str());
            if (params::isFanucParameterNumber(n)) {
                if (auto refused = params::refusedFanucParameter(n, v)) {
                    fail(file, *refused, value.source());
                }
                if (auto unread = params::unreadFanucParameter(n)) {
                    config.warn(warningAt(file, value.source(), *unread));
                }
                config.fanucParameters[n] = v;
                config.fanucParameterOrigins[n] = placeOf(file, value.source());
                continue;
            }
            if (auto refused = params::refusedParameterValue(n, v)) {
                fail(file, *refused, value.source());
            }
            // A value the panel would refuse is kept (a simulator may be asked for it) but said; the
            // other members of the IO triples (enable, level) are not catalogued and pass as written.
            if (known && known->find(n)) {
                if (auto problem = known->validate(n, v)) {
                    const Message kept = message("param_kept_as_written", {file.string(), bilingual(*problem)});
                    config.warn(kept);
                }
            }
            config.parameters.set(n, v);
        }
    }
    if (auto refused = rebuildCallCodes(config)) {
        const toml::node* setting = t["params"].as_table()->get(std::to_string(refused->parameter));
        fail(file, refused->message, setting ? setting->source() : toml::source_region{});
    }
}

void loadOffsets(const fs::path& folder, MachineConfig& config) {
    fs::path file = folder / MachineFolder::fileName(FolderFile::Offsets);
    if (!fs::exists(file)) {
        return;
    }
    toml::table t = parseToml(file);
    warnUnknownKeys(file, t, {"G92", "G54", "G55", "G56", "G57", "G58", "G59", "G52", "common"}, config);
    static constexpr std::pair<const char*, int> slots[] = {{"G92", 0}, {"G54", 1}, {"G55", 2}, {"G56", 3},
                                                            {"G57", 4}, {"G58", 5}, {"G59", 6}, {"G52", 7},
                                                            {"common", 8}};
    for (auto [name, slot] : slots) {
        if (const toml::node* given = t.get(name); given && !given->is_array()) {
            fail(file, message("config_axes_list", {name}), given->source());
        }
        if (auto axes = t[name].as_array()) {
            if (axes->size() > 5) {
                fail(file, message("config_axes_too_many", {name}), axes->source());
            }
            for (std::size_t i = 0; i < axes->size(); ++i) {
                config.offsets[static_cast<std::size_t>(slot)][i] = numberValue(file, *axes->get(i), name);
            }
            if (axes->size() < 3) {
                config.warn(warningAt(file, axes->source(),
                                      axes->size() == 1 ? message("config_axes_one", {name})
                                                        : message("config_axes_few", {name, std::to_string(axes->size())})));
            }
        }
    }
}

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

// tool.tbl: a refused line is a warning (the rest loads). On the M350 the table's Z replaces the
// tool's parameter; a different non-zero value in params.toml is said.
void loadToolTable(const fs::path& folder, MachineConfig& config) {
    fs::path file = folder / MachineFolder::fileName(FolderFile::ToolTable);
    if (!fs::exists(file)) {
        return;
    }
    std::string text;
    if (auto why = files::readMachineFile(file, text)) {
        fail(file, message("config_tool_table_unreadable", {bilingual(*why)}));
    }
    tools::ParsedToolTable parsed = tools::parseToolTable(text, file.string());
    for (const tools::ToolTableIssue& issue : parsed.issues) {
        config.warn(tools::formatIssue(issue), tools::formatIssue(issue, MessageLanguage::Chinese));
    }
    if (parsed.issues.empty()) {
        files::refreshLastGood(file);
    } else if (!files::lastGoodNote(file).empty()) {
        config.warn(linesNotRead(file));
    }
    const std::vector<tools::ToolTable::Line>& lines = parsed.table.lines();
    for (std::size_t i = 0; config.dialect->id == gcode::DialectId::M350 && i < lines.size(); ++i) {
        const std::optional<tools::ToolEntry>& row = lines[i].entry;
        std::optional<int> parameter = row ? tools::m350ZParameter(row->tool, config.parameters) : std::nullopt;
        if (!parameter || !row->offsets[tools::kZ]) {
            continue;
        }
        const double inParams = config.parameters.get(*parameter);
        if (inParams != 0.0 && inParams != *row->offsets[tools::kZ]) {
            config.warn(warningIn(folder / MachineFolder::fileName(FolderFile::Params),
                                  message("config_z_mismatch",
                                          {std::to_string(*parameter), std::to_string(row->tool), tools::tableNumber(inParams),
                                           file.string(), std::to_string(i + 1),
                                           tools::tableNumber(*row->offsets[tools::kZ])})));
        }
    }
    config.toolTable = std::move(parsed.table);
    config.toolTableFile = file.string();
}

} // namespace

std::variant<MachineConfig, ConfigError> loadMachineFolder(const std::string& folder) {
    MachineConfig config;
    fs::path dir(folder);
    config.folder = folder;
    try {
        if (!fs::is_directory(dir)) {
            fail(dir, message("config_not_a_folder"));
        }
        // a save a crash interrupted is finished (or dropped) before any file is read
        if (auto broken = MachineFolder(dir).finishInterruptedChange()) {
            fail(dir / MachineFolder::kChangeJournal, message("config_journal_broken", {bilingual(*broken)}));
        }
        loadMachineToml(dir, config);
        loadParams(dir, config);
        loadOffsets(dir, config);
        loadVariables(dir, config);
        if (auto wrong = loadModbusSlaves((dir / MachineFolder::fileName(FolderFile::Modbus)).string(), config.modbus)) {
            fail(dir / MachineFolder::fileName(FolderFile::Modbus), *wrong);
        }
        loadToolTable(dir, config);
        tools::LifeData lifeSettings;
        if (config.dialect->id == gcode::DialectId::Fanuc) {
            lifeSettings.applyFanucParameters(config.fanucParameters);
        }
        auto life = tools::loadToolLife(folder, lifeSettings.fromParameters ? &lifeSettings : nullptr);
        if (auto* unreadable = std::get_if<Message>(&life)) {
            fail(dir / MachineFolder::fileName(FolderFile::ToolLife),
                 message("config_tool_life_unreadable", {bilingual(*unreadable)}));
        }
        tools::ParsedToolLife& parsed = std::get<tools::ParsedToolLife>(life);
        for (const tools::LifeFileIssue& issue : parsed.issues) {
            config.warn(issue.text(), issue.text(MessageLanguage::Chinese));
        }
        const fs::path lifeFile = dir / MachineFolder::fileName(FolderFile::ToolLife);
        if (parsed.issues.empty()) {
            files::refreshLastGood(lifeFile);
        } else if (!files::lastGoodNote(lifeFile).empty()) {
            config.warn(linesNotRead(lifeFile));
        }
        config.toolLife = std::move(parsed.data);
        config.toolLifeIssues = std::move(parsed.issues);
        if (auto wrong = tools::readLoadMonitorSettings((dir / tools::kSpindleLoadFileName).string(), config.loadMonitor)) {
            return ConfigError{(dir / tools::kSpindleLoadFileName).string(), message("config_spindle_load_wrong", {bilingual(wrong->message)}),
                               wrong->line, wrong->column};
        }
        files::refreshLastGood(dir / MachineFolder::fileName(FolderFile::Params));
    } catch (const Failure& f) {
        ConfigError error = f.error;
        if (!files::lastGoodNote(error.file).empty()) {
            error.message = message("config_last_good", {bilingual(error.message), files::lastGoodPath(error.file).string()});
        }
        return error;
    } catch (const fs::filesystem_error& e) {
        // a symlink loop, a dangling link, a folder that cannot be listed: an error, not an abort
        return ConfigError{e.path1().empty() ? folder : e.path1().string(), message("config_system_error", {e.code().message()})};
    }
    return config;
}

std::string ConfigError::where() const {
    if (line <= 0) {
        return file;
    }
    return file + ":" + std::to_string(line) + (column > 0 ? ":" + std::to_string(column) : std::string());
}

std::string ConfigError::text(MessageLanguage language) const {
    return where() + ": " + message.in(language);
}

std::string bundledMachinesDirectory() {
    return resourceDirectory() + "/machines";
}

} // namespace m350::config
