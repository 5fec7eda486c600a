#pragma once

#include "core/common/Message.h"
#include "core/config/InterfaceSignals.h"
#include "core/config/MagazineConfig.h"
#include "core/config/ModbusSlaves.h"
#include "core/params/ParameterTable.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/Program.h"
#include "core/macro/VariableLayout.h"
#include "core/machine/SimulatedMachine.h"
#include "core/machine/SpindleLoadModel.h"
#include "core/macro/CallCodes.h"
#include "core/tools/SpindleLoadLimits.h"
#include "core/tools/ToolData.h"
#include "core/tools/ToolTable.h"
#include "core/tools/ToolLifeFile.h"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace m350::config {

struct LibraryFile {
    std::string path;
    gcode::FileRole role = gcode::FileRole::Library;
};

// A machine folder, as loaded: which dialect it speaks, its macro libraries, its parameters and
// offsets, and the wiring of its IO. Files:
//   machine.toml   name, dialect, [libraries], [codes], [[io_links]], [magazine], [reference_points], [homing],
//                  [tool_setter], [floating_setter], [tools], [tool_data], [interface_signals],
//                  [variables] common, [coordinates] (FANUC options)
//   params.toml    [params] N = value (parameters 0-999; on an M350 the rest take their factory
//                  values from the catalogue, uncatalogued ones 0; FANUC machines: the rest 0, and
//                  also 1000-99999)
//   offsets.toml   optional: G92/G54..G59/G52/common = [X, Y, Z, A, B]
//   variables.toml optional: [variables] N = value (FANUC retained #500-#999 and other stored values)
//   tool.tbl       optional: the tool table in LinuxCNC's format (core/tools/ToolTableFile.h); on the
//                  M350 its Z column replaces params 930-945 / 973-992 of params.toml
//   hook files     optional: the M350's fndzero.nc, probe.nc, key-1.nc ... (HookFiles.h); slibuser.nc
//                  is loaded as a G library beside the listed ones
//   modbus.toml    optional: the Modbus RTU slaves' registers and coils (ModbusSlaves.h)
//   toollife.txt   optional: tool life management groups (core/tools/ToolLifeFile.h)
//   spindle-load.toml optional: the breakage monitor's per-tool load limits (core/tools/SpindleLoadLimits.h)
struct MachineConfig {
    std::string folder;
    std::string name;
    std::string nameZh; // machine.toml's name_zh: what the Chinese panel calls it (empty: `name`)
    const gcode::Dialect* dialect = &gcode::Dialect::m350();
    std::vector<LibraryFile> libraries;
    macro::CallCodes codeCalls; // machine.toml's [codes]: M6 = 9001 (a subprogram call)
    // The codes that call programs, as runs use them: [codes] and a FANUC's parameters 6050-6091
    // (CallCodeParameters.h, rebuildCallCodes)
    macro::CallCodes callCodes;
    std::vector<machine::IoLink> ioLinks;
    params::ParameterTable parameters;
    std::map<int, double> fanucParameters; // FANUC machines' parameters 1000-99999 (FanucParameters.h)
    std::map<int, std::string> fanucParameterOrigins; // where each was set, for messages: "params.toml:4:8"
    std::array<std::array<double, 5>, 9> offsets{}; // slots as interp::WorkOffsets numbers them
    std::map<int, double> variables;
    // FANUC options the control has: [variables] common = ["100-499", ...] and [coordinates]
    // additional_systems (G54.1 P1-Pn); unset, the dialect's (VariableLayout)
    macro::VariableLayout variableLayout;
    std::optional<bool> coordinateRotation; // [coordinates] rotation (G68/G69); unset: FANUC yes, M350 no
    bool rotation() const { return coordinateRotation.value_or(dialect->id == gcode::DialectId::Fanuc); }
    int additionalWorkSystems() const { return variableLayout.workSystems(*dialect); }
    int magazineCapacity = 0; // machines whose capacity is not a parameter (FANUC)
    std::vector<std::string> warnings; // values the panel would refuse, kept as written (English)
    std::map<std::size_t, std::string> warningsChinese; // a warning's Chinese, by its index in `warnings`
    void warn(std::string english, std::string chinese) {
        warningsChinese[warnings.size()] = std::move(chinese);
        warnings.push_back(std::move(english));
    }
    void warn(const Message& words) { warn(words.english(), words.in(MessageLanguage::Chinese)); }
    // The i-th warning in `language` (English where it has no Chinese).
    const std::string& warning(std::size_t i, MessageLanguage language) const {
        auto chinese = language == MessageLanguage::Chinese ? warningsChinese.find(i) : warningsChinese.end();
        return chinese != warningsChinese.end() ? chinese->second : warnings[i];
    }
    std::map<int, std::array<double, 5>> referencePoints; // G30 P2/P3 (FANUC G28: point 1), machine coordinates
    // The simulated world: how far each axis travels from where it stands at power-on to its home
    // switch ([homing] switch_distance = [X, Y, Z, A, B]); no parameter says this.
    std::array<double, 5> homeSwitchDistance{100.0, 100.0, 50.0, 30.0, 30.0};
    MagazineConfig magazine; // [magazine]: the device beside the machine, if any
    InterfaceSignals interfaceSignals; // [interface_signals]: a FANUC's #1000-#1015, #1032, #1100-#1133
    // The fixed tool setter's top ([tool_setter] top: spindle-nose machine Z at contact with a
    // zero-length tool) and reach; the tools' true lengths ([tools] length = [T1, T2, ...], mm).
    double setterTop = -100.0;
    double setterRadius = 5.0;
    // The floating setter ([floating_setter] top): a block of param 129's thickness lying on the
    // work, as spindle-nose machine Z at contact with a zero-length tool; none when not given.
    std::optional<double> floatingSetterTop;
    std::vector<double> toolLengths;
    std::vector<double> toolDiameters; // [tools] diameter = [T1, T2, ...], mm: how wide they cut
    // [stock] and [spindle_load]: where the simulated spindle load comes from (none: no load signal)
    std::optional<machine::SpindleLoadModel> spindleLoad;
    tools::LoadMonitorSettings loadMonitor; // spindle-load.toml
    ModbusSlaves modbus; // modbus.toml
    // tool.tbl as read (refused lines are in `warnings` with file:line:col); nullopt when the folder
    // has none: an M350 then starts its table from params 930-945 (tools::ToolData).
    std::optional<tools::ToolTable> toolTable;
    std::string toolTableFile; // where toolTable was read (G10 L0 reads it again); empty: none
    // [tool_data] in machine.toml: the FANUC offset memory, LinuxCNC's random tool changer.
    tools::OffsetMemory offsetMemory = tools::OffsetMemory::A;
    bool randomToolChanger = false;
    tools::LifeData toolLife; // toollife.txt
    // its skipped lines (also in `warnings` as text); the lines themselves stay in toolLife.unreadLines
    std::vector<tools::LifeFileIssue> toolLifeIssues;
};

struct ConfigError {
    std::string file;
    Message message; // by id: m350-sim --lang and the panel say it in their language
    int line = 0; // 1-based where the file says what is wrong; 0 when the whole file is
    int column = 0;
    // "file:line:col", "file:line" or "file", as messages name a place
    std::string where() const;
    // "where: message" in `language`, as the CLI and the panel print it
    std::string text(MessageLanguage language) const;
};

std::variant<MachineConfig, ConfigError> loadMachineFolder(const std::string& folder);

// The bundled machine folders: resourceDirectory()/machines (installed share folder or source tree).
std::string bundledMachinesDirectory();
inline constexpr const char* kDefaultMachine = "m350-linear16";
// The environment variable naming one more folder machine.toml's libraries may lie in.
inline constexpr const char* kLibrariesVariable = "M350_LIBRARIES";

} // namespace m350::config
