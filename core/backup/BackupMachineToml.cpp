#include "core/backup/BackupMachineToml.h"

#include "core/common/Numeric.h"
#include "core/params/IoPorts.h"
#include "core/params/ParameterNumbers.h"
#include "core/params/ParamsFileWriter.h"

#include <algorithm>
#include <optional>

namespace m350::backup {

namespace {

constexpr double kAssumedToolLength = 60.0;  // mm, a tool whose length nothing gives
constexpr double kDefaultSetterTop = -100.0; // as MachineConfig, when no tool was ever set
constexpr double kSetterRadius = 5.0;
constexpr double kFloatingBelowSetter = 10.0; // the floating block's top under the fixed setter's
constexpr double kSetterBelowStart = 20.0;    // a tool of the assumed length trips this far below param 137
constexpr int kVirtualTools = 20;
constexpr double kSwitchDistance[] = {100.0, 100.0, 50.0, 30.0, 30.0};

std::string list(const std::vector<double>& values) {
    std::string text = "[";
    for (std::size_t i = 0; i < values.size(); ++i) {
        text += (i ? ", " : "") + params::tomlNumber(values[i]);
    }
    return text + "]";
}

// Where tool k tripped the fixed setter (machine Z of the spindle nose), when it was ever set:
// params 930-945 for pockets 1-16, 973-992 for the virtual tools above the capacity.
std::optional<double> storedOffset(const params::ParameterTable& p, int tool, int capacity) {
    double z = 0.0;
    if (tool <= capacity && tool <= param::kToolZOffsetCount) {
        z = p.get(param::kToolZOffsetFirst + tool - 1);
    } else if (tool > capacity && tool - capacity <= param::kVirtualToolZOffsetCount) {
        z = p.get(param::kVirtualToolZOffsetFirst + tool - capacity - 1);
    }
    return z != 0.0 ? std::optional<double>(z) : std::nullopt;
}

void libraries(const ControllerBackup& backup, ImportedMachine& out) {
    std::string text = "[libraries]\n";
    for (auto [key, name] : {std::pair{"g", "slib-g.nc"}, std::pair{"m", "slib-m.nc"}}) {
        if (const BackupFile* library = findProgram(backup, name)) {
            text += std::string(key) + " = \"" + library->name + "\"\n";
            out.libraries.push_back(library->name);
        } else {
            out.unsupported.push_back(message(key == std::string("g") ? "import_no_library_g" : "import_no_library_m", {name}));
        }
    }
    if (const BackupFile* user = findProgram(backup, "slibuser.nc")) {
        text += "# " + user->name + " (G100-G199) is loaded beside slib-g.nc because it is in the folder\n";
        out.libraries.push_back(user->name);
    }
    out.text += text;
}

void world(const ControllerBackup& backup, ImportedMachine& out) {
    const params::ParameterTable& p = backup.setting;
    const int capacity = std::clamp(saturatingInt(p.get(param::kMagazineCapacity)), 0, 20);
    const int virtualTools = p.get(param::kVirtualTools) != 0.0 ? kVirtualTools : 0;
    const int current = std::clamp(saturatingInt(p.get(param::kCurrentTool)), 0, capacity + kVirtualTools);
    const int tools = std::max({capacity + virtualTools, current, 1});
    std::optional<double> lowest;
    for (int k = 1; k <= tools; ++k) {
        if (auto z = storedOffset(p, k, capacity)) {
            lowest = std::min(lowest.value_or(*z), *z);
        }
    }
    const double start = p.get(param::kFixedSetterX + 2);
    const double top = atFourDecimals(lowest ? *lowest - kAssumedToolLength
                                      : start != 0.0 ? start - kAssumedToolLength - kSetterBelowStart
                                                     : kDefaultSetterTop);
    std::vector<double> lengths;
    int set = 0;
    for (int k = 1; k <= tools; ++k) {
        auto z = storedOffset(p, k, capacity);
        set += z ? 1 : 0;
        lengths.push_back(z ? atFourDecimals(*z - top) : kAssumedToolLength);
    }
    const std::vector<double> distances(std::begin(kSwitchDistance), std::end(kSwitchDistance));
    out.text += "\n# The simulated world: facts no file of the backup gives. Stated, to be reviewed.\n"
                "# How far each axis stands from its home switch at power-on (mm).\n[homing]\nswitch_distance = " +
                list(distances) + "\n";
    out.review.push_back({"homing.switch_distance", list(distances),
                          message("import_review_switch_distance")});
    out.text += "\n# The fixed setter's top: spindle-nose machine Z at contact with a zero-length tool.\n"
                "[tool_setter]\ntop = " + params::tomlNumber(top) + "\nradius = " + params::tomlNumber(kSetterRadius) + "\n";
    out.review.push_back(
        {"tool_setter.top", params::tomlNumber(top),
         message(lowest ? "import_review_setter_lowest"
                 : start != 0.0 ? "import_review_setter_start" : "import_review_setter_default")});
    if (params::wiredInput(p, param::kFloatingSetterInput)) {
        const std::string floatingTop = params::tomlNumber(atFourDecimals(top - kFloatingBelowSetter));
        out.text += "\n# The floating setter: a block of param 129's thickness lying on the work.\n"
                    "[floating_setter]\ntop = " + floatingTop + "\n";
        out.review.push_back({"floating_setter.top", floatingTop,
                              message("import_review_floating")});
    }
    out.text += "\n# Tool lengths T1..T" + std::to_string(tools) +
                " (mm): the stored Z offset minus the setter's top, 60 for a tool never set.\n[tools]\nlength = " +
                list(lengths) + "\n";
    out.review.push_back({"tools.length", bilingual(message("import_review_tool_count", {std::to_string(tools)})),
                          message("import_review_tool_lengths", {std::to_string(set), std::to_string(tools - set)})});
}

// Params 488-492 give each motor output the programmed axis it drives. A 4th or 5th motor driving
// Y or Z is the second motor of a gantry (a dual-Y router: 491 = 1; an owner's fndzero.nc then
// writes #883=#881). X is left out: 0 is also the value of a motor never set.
void gantryMotors(const params::ParameterTable& p, ImportedMachine& out) {
    for (int motor = 4; motor <= 5; ++motor) {
        const int n = param::kMotorAxisFirst + motor - 1;
        const double axis = p.get(n);
        if (axis != 1.0 && axis != 2.0) {
            continue;
        }
        const char* programmed = axis == 1.0 ? "Y" : "Z";
        const Message own = message(motor == 4 ? "import_gantry_axis_4" : "import_gantry_axis_5");
        out.unsupported.push_back(message("import_gantry_motor",
                                          {std::to_string(motor), programmed, std::to_string(n), params::tomlNumber(axis),
                                           bilingual(own), std::to_string(880 + motor - 1),
                                           std::to_string(880 + static_cast<int>(axis)), "fndzero.nc"}));
    }
}

} // namespace

ImportedMachine formatImportedMachine(const ControllerBackup& backup) {
    ImportedMachine out;
    out.text = "# A machine imported from an M350 controller backup (`m350-sim import`). params.toml, offsets.toml\n"
               "# and mdiblock come from the controller's own files, the .nc files are copied as they were.\n"
               "name = \"M350 imported from a controller backup\"\ndialect = \"m350\"\n\n";
    libraries(backup, out);
    ImportedWiring wiring = importWiring(backup.setting);
    out.magazine = wiring.magazine;
    out.text += "\n# " + wiring.magazine.english() + "\n" + (wiring.magazineToml.empty() ? "" : wiring.magazineToml);
    out.text += wiring.linksToml;
    world(backup, out);
    out.review.insert(out.review.begin(), wiring.review.begin(), wiring.review.end());
    out.unsupported.insert(out.unsupported.end(), wiring.unsupported.begin(), wiring.unsupported.end());
    gantryMotors(backup.setting, out);
    return out;
}

} // namespace m350::backup
