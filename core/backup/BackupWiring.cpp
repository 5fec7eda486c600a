#include "core/backup/BackupWiring.h"

#include "core/common/Numeric.h"
#include "core/params/IoPorts.h"
#include "core/params/ParameterNumbers.h"
#include "core/params/ParamsFileWriter.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace m350::backup {

namespace {

constexpr int kRackPositions = 16;        // params 830-845 / 850-865 / 870-885
constexpr int kMostHeads = 4;             // cylinders 777, 780, 783, 786
constexpr double kClampDelayMs = 150.0;   // a clamp cylinder, unless param 814 says
constexpr double kSlideDelayMs = 600.0;   // a magazine slide's stroke
constexpr double kCoverDelayMs = 500.0;   // a dust cover's stroke
constexpr int kDustCoverInput = 632;      // 除尘罩检测 (M305/M306)
constexpr int kDustCoverOutput = 762;     // 除尘罩打开/关闭 (M150/M151)
constexpr int kMagazineOutInput = 629;    // 刀库推出检测 (M303)
constexpr int kMagazineInInput = 697;     // 刀库收回检测 (M304)

struct TypeName {
    const char* en;
    const char* zh;
};
constexpr TypeName kTypes[] = {{"none", "无刀库"},
                               {"multi-process", "多工序"},
                               {"follow row on the gantry", "龙门架直排"},
                               {"fixed row", "固定直排"},
                               {"servo disc", "圆盘刀库"}};

// "magazine type 2 (follow row on the gantry, 龙门架直排)", as a message argument.
std::string typeText(int type) {
    return bilingual(message("import_magazine_type",
                             {std::to_string(type), bilingual(std::string(kTypes[type].en) + ", " + kTypes[type].zh,
                                                              kTypes[type].zh)}));
}

// Pockets 1.. with a position, as the rack device counts them: it ends at the first one unset.
int pocketsWithPositions(const params::ParameterTable& p, int capacity, bool onGantry) {
    int k = 0;
    while (k < std::min(capacity, kRackPositions)) {
        const double x = p.get(param::kPocketX + k), y = p.get(param::kPocketY + k), z = p.get(param::kPocketZ + k);
        if (x == 0.0 && z == 0.0 && (onGantry || y == 0.0)) {
            break;
        }
        ++k;
    }
    return k;
}

// The [magazine] table for param 802, or none with the reason.
void importMagazine(const params::ParameterTable& p, ImportedWiring& out) {
    const double typeValue = p.get(param::kMagazineType);
    const int capacity = saturatingInt(p.get(param::kMagazineCapacity));
    const int type = saturatingInt(typeValue);
    if (typeValue != std::floor(typeValue) || type < 0 || type > 4) {
        out.magazine = message("import_magazine_unknown", {params::tomlNumber(typeValue)});
        out.unsupported.push_back(message("import_magazine_bad_type", {params::tomlNumber(typeValue)}));
        return;
    }
    const auto said = [&](const char* id, std::vector<std::string> more = {}) {
        more.insert(more.begin(), {typeText(type), std::to_string(capacity)});
        return message(id, std::move(more));
    };
    if (type == 0) {
        out.magazine = said(p.get(param::kVirtualTools) != 0.0 ? "import_magazine_none_virtual" : "import_magazine_none");
        return;
    }
    if (type == 4) {
        out.magazine = said("import_magazine_not_modelled");
        out.unsupported.push_back(message("import_disc_not_modelled", {typeText(4), "[magazine] device = \"servo-disc\"",
                                                                       "resources/machines/m350-servo-disc"}));
        return;
    }
    if (capacity < 1) {
        out.magazine = said("import_magazine_no_pockets");
        out.unsupported.push_back(message("import_magazine_capacity_zero", {typeText(type)}));
        return;
    }
    if (type == 1) {
        if (capacity > kMostHeads) {
            out.magazine = said("import_magazine_not_modelled");
            out.unsupported.push_back(message("import_multi_too_many", {typeText(1), std::to_string(capacity)}));
            return;
        }
        out.magazine = said("import_magazine_multi_head", {std::to_string(capacity)});
        out.magazineToml = "[magazine]\ndevice = \"multi-head\"\ntolerance = 1.0\n";
        return;
    }
    const bool onGantry = type == 2;
    const int pockets = pocketsWithPositions(p, capacity, onGantry);
    if (pockets == 0) {
        out.magazine = said("import_magazine_no_positions");
        out.unsupported.push_back(message("import_rack_no_position", {typeText(type)}));
        return;
    }
    if (pockets < capacity) {
        out.unsupported.push_back(message(
            "import_rack_short", {std::to_string(pockets), std::to_string(capacity), std::to_string(pockets + 1)}));
    }
    out.magazine = said(onGantry ? "import_magazine_rack_gantry" : "import_magazine_rack_top", {std::to_string(pockets)});
    if (onGantry) {
        out.magazineToml = "[magazine]\ndevice = \"linear-rack\"\ncarried = \"gantry\"\nslide_travel = 100.0\n"
                           "fork_depth = 30.0\ntolerance = 1.0\n";
        out.review.push_back({"magazine.slide_travel", "100.0", message("import_review_slide_travel")});
        out.review.push_back({"magazine.fork_depth", "30.0", message("import_review_fork_depth")});
    } else {
        out.magazineToml = "[magazine]\ndevice = \"linear-rack\"\nloading = \"top\"\nfork_depth = 40.0\n"
                           "tolerance = 1.0\n";
        out.review.push_back({"magazine.loading", "\"top\"",
                              message("import_review_loading", {"loading = \"side\"", "opening = \"+Y\"", "\"-Y\""})});
        out.review.push_back({"magazine.fork_depth", "40.0", message("import_review_fork_depth")});
    }
}

struct Link {
    int outputParameter;
    int inputParameter;
    bool follows; // the input is active while the output is; else while it is not
    double delayMs;
    const char* why;
    const char* whyZh;
};

// [[io_links]] for the sensors whose actuator the IO page wires and no device drives: the input
// follows (or opposes) the output after the actuator's stroke. Returns the inputs it linked.
std::vector<int> importLinks(const params::ParameterTable& p, bool device, ImportedWiring& out) {
    const double lockMs = p.get(param::kSpindleLockDelay);
    const double clampMs = lockMs > 1.0 ? lockMs : kClampDelayMs;
    std::vector<Link> links;
    if (!device) { // a device moves its own clamp cylinder and drives its sensors
        links.push_back({param::kDrawbarOutput, param::kToolReleasedInput, true, clampMs, "tool released", "刀具松开"});
        links.push_back({param::kDrawbarOutput, param::kToolClampedInput, false, clampMs, "tool clamped", "刀具锁紧"});
    }
    links.push_back({param::kMagazineSlideOutput, kMagazineOutInput, true, kSlideDelayMs, "magazine out", "刀库推出"});
    links.push_back({param::kMagazineSlideOutput, kMagazineInInput, false, kSlideDelayMs, "magazine in", "刀库收回"});
    links.push_back({kDustCoverOutput, kDustCoverInput, true, kCoverDelayMs, "dust cover open", "除尘罩打开"});
    std::vector<int> linked;
    std::string sensors;
    std::string sensorsZh;
    for (const Link& link : links) {
        const params::PortAssignment output = params::portAssignment(p, link.outputParameter);
        const std::optional<params::PortAssignment> input = params::wiredInput(p, link.inputParameter);
        if (!output.wired() || output.pin > 21 || !input) {
            continue;
        }
        const bool sameLevel = output.activeLevel == input->activeLevel;
        out.linksToml += "\n# " + params::inputName(input->pin) + " (" + link.why + ", param " +
                         std::to_string(link.inputParameter) + ") " + (link.follows ? "follows " : "opposes ") +
                         params::outputName(output.pin) + " (param " + std::to_string(link.outputParameter) + ")\n";
        out.linksToml += "[[io_links]]\noutput = " + std::to_string(output.pin) +
                         "\ninput = " + std::to_string(input->pin) + "\ndelay_ms = " + params::tomlNumber(link.delayMs) +
                         "\ninverted = " + (link.follows != sameLevel ? "true" : "false") + "\n";
        linked.push_back(link.inputParameter);
        sensors += (sensors.empty() ? "" : ", ") + params::inputName(input->pin) + " " + link.why;
        sensorsZh += (sensorsZh.empty() ? "" : "，") + params::inputName(input->pin) + link.whyZh;
    }
    if (!linked.empty()) {
        out.review.push_back({"io_links", bilingual(sensors, sensorsZh), message("import_review_io_links")});
    }
    return linked;
}

// Wired inputs that nothing in the simulation drives: sensors a macro waits for, and the alarm and
// limit inputs the simulation never trips.
void reportUndrivenInputs(const params::ParameterTable& p, bool device, const std::vector<int>& linked,
                          ImportedWiring& out) {
    static constexpr int sensors[] = {param::kToolReleasedInput, param::kToolClampedInput, kMagazineOutInput,
                                      kMagazineInInput, kDustCoverInput};
    std::string neverActive;
    std::string neverActiveZh;
    for (const params::IoFunction& function : params::ioFunctions()) {
        const std::optional<params::PortAssignment> input = function.input ? params::wiredInput(p, function.parameter) : std::nullopt;
        if (!input) {
            continue;
        }
        const int n = function.parameter;
        const bool drawbar = n == param::kToolReleasedInput || n == param::kToolClampedInput;
        const bool sensor = std::find(std::begin(sensors), std::end(sensors), n) != std::end(sensors);
        if (sensor && !(drawbar && device) && std::find(linked.begin(), linked.end(), n) == linked.end()) {
            out.unsupported.push_back(message("import_sensor_undriven", {params::inputName(input->pin),
                                                                         bilingual(function.nameEn, function.nameZh),
                                                                         std::to_string(n), "sensor_timeout"}));
        }
        const bool alarmOrLimit = (n >= 500 && n <= 542) || (n >= 635 && n <= 650);
        if (alarmOrLimit) {
            neverActive += (neverActive.empty() ? "" : ", ") + std::string(function.nameEn) + " " +
                           params::inputName(input->pin);
            neverActiveZh += (neverActiveZh.empty() ? "" : "，") + std::string(function.nameZh) + params::inputName(input->pin);
        }
    }
    if (!neverActive.empty()) {
        out.unsupported.push_back(message("import_inputs_never_active", {bilingual(neverActive, neverActiveZh)}));
    }
    static constexpr const char* axes[] = {"X", "Y", "Z"};
    for (int axis = 0; axis < 3; ++axis) {
        if (!params::wiredInput(p, param::kHomeSwitchX + 3 * axis)) {
            out.unsupported.push_back(
                message("import_no_home_switch", {axes[axis], std::to_string(param::kHomeSwitchX + 3 * axis)}));
        }
    }
}

} // namespace

ImportedWiring importWiring(const params::ParameterTable& parameters) {
    ImportedWiring out;
    importMagazine(parameters, out);
    const bool device = !out.magazineToml.empty();
    const std::vector<int> linked = importLinks(parameters, device, out);
    reportUndrivenInputs(parameters, device, linked, out);
    return out;
}

} // namespace m350::backup
