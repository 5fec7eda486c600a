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

std::string typeText(int type) {
    return "magazine type " + std::to_string(type) + " (" + kTypes[type].en + ", " + kTypes[type].zh + ")";
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
        out.magazine = "magazine type " + params::tomlNumber(typeValue) + " (param 802): unknown, no magazine device";
        out.unsupported.push_back("param 802 = " + params::tomlNumber(typeValue) +
                                  " is no M350 magazine type (0-4): the machine has no magazine device");
        return;
    }
    const std::string what = typeText(type) + ", capacity " + std::to_string(capacity);
    if (type == 0) {
        out.magazine = what + ": no magazine device" +
                       (p.get(param::kVirtualTools) != 0.0 ? "; virtual tools are changed by hand (params 816-818)" : "");
        return;
    }
    if (type == 4) {
        out.magazine = what + ": not modelled, no magazine device";
        out.unsupported.push_back(
            typeText(4) + " is not modelled from a backup: the factory O20000 leaves it unimplemented and no "
                          "parameter says how the disc's drive is wired (pocket select outputs, start, in-position "
                          "input). T runs your O20000 but no disc follows it; once you know the wiring, add "
                          "[magazine] device = \"servo-disc\" as resources/machines/m350-servo-disc does");
        return;
    }
    if (capacity < 1) {
        out.magazine = what + ": no magazine device (no pockets)";
        out.unsupported.push_back(typeText(type) + " with capacity 0 (param 801): no magazine device");
        return;
    }
    if (type == 1) {
        if (capacity > kMostHeads) {
            out.magazine = what + ": not modelled, no magazine device";
            out.unsupported.push_back(typeText(1) + " with " + std::to_string(capacity) +
                                      " heads: the simulator models at most 4 (the IO page's cylinders 1-4)");
            return;
        }
        out.magazine = what + ": multi-head device, " + std::to_string(capacity) + " heads";
        out.magazineToml = "[magazine]\ndevice = \"multi-head\"\ntolerance = 1.0\n";
        return;
    }
    const bool onGantry = type == 2;
    const int pockets = pocketsWithPositions(p, capacity, onGantry);
    if (pockets == 0) {
        out.magazine = what + ": no magazine device (no pocket positions)";
        out.unsupported.push_back(typeText(type) + ": pocket 1 has no position (params 830/850/870), so there is "
                                                   "no rack to model: no magazine device");
        return;
    }
    if (pockets < capacity) {
        out.unsupported.push_back(
            "the rack has positions for " + std::to_string(pockets) + " of its " + std::to_string(capacity) +
            " pockets (params 830-885 hold 16 and the rack ends at the first pocket without one): tools " +
            std::to_string(pockets + 1) + "-" + std::to_string(capacity) + " have no pocket in the simulation");
    }
    out.magazine = what + ": linear-rack device, " + std::to_string(pockets) + " pockets" +
                   (onGantry ? ", carried on the gantry" : ", loaded from above");
    if (onGantry) {
        out.magazineToml = "[magazine]\ndevice = \"linear-rack\"\ncarried = \"gantry\"\nslide_travel = 100.0\n"
                           "fork_depth = 30.0\ntolerance = 1.0\n";
        out.review.push_back({"magazine.slide_travel", "100.0",
                              "how far the slide (output of param 753) pushes the forks out to the spindle"});
        out.review.push_back({"magazine.fork_depth", "30.0", "how deep a tool sits in its fork"});
    } else {
        out.magazineToml = "[magazine]\ndevice = \"linear-rack\"\nloading = \"top\"\nfork_depth = 40.0\n"
                           "tolerance = 1.0\n";
        out.review.push_back({"magazine.loading", "\"top\"",
                              "the factory O20000 puts a tool down into its fork from above; if yours slides it "
                              "in from the side, write loading = \"side\" and opening = \"+Y\" or \"-Y\""});
        out.review.push_back({"magazine.fork_depth", "40.0", "how deep a tool sits in its fork"});
    }
}

struct Link {
    int outputParameter;
    int inputParameter;
    bool follows; // the input is active while the output is; else while it is not
    double delayMs;
    const char* why;
};

// [[io_links]] for the sensors whose actuator the IO page wires and no device drives: the input
// follows (or opposes) the output after the actuator's stroke. Returns the inputs it linked.
std::vector<int> importLinks(const params::ParameterTable& p, bool device, ImportedWiring& out) {
    const double lockMs = p.get(param::kSpindleLockDelay);
    const double clampMs = lockMs > 1.0 ? lockMs : kClampDelayMs;
    std::vector<Link> links;
    if (!device) { // a device moves its own clamp cylinder and drives its sensors
        links.push_back({param::kDrawbarOutput, param::kToolReleasedInput, true, clampMs, "tool released"});
        links.push_back({param::kDrawbarOutput, param::kToolClampedInput, false, clampMs, "tool clamped"});
    }
    links.push_back({param::kMagazineSlideOutput, kMagazineOutInput, true, kSlideDelayMs, "magazine out"});
    links.push_back({param::kMagazineSlideOutput, kMagazineInInput, false, kSlideDelayMs, "magazine in"});
    links.push_back({kDustCoverOutput, kDustCoverInput, true, kCoverDelayMs, "dust cover open"});
    std::vector<int> linked;
    std::string sensors;
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
    }
    if (!linked.empty()) {
        out.review.push_back({"io_links", sensors,
                              "each sensor follows its actuator's output after a stroke time the backup does not "
                              "give (clamp: param 814 or 150 ms, slide 600 ms, dust cover 500 ms)"});
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
    for (const params::IoFunction& function : params::ioFunctions()) {
        const std::optional<params::PortAssignment> input = function.input ? params::wiredInput(p, function.parameter) : std::nullopt;
        if (!input) {
            continue;
        }
        const int n = function.parameter;
        const bool drawbar = n == param::kToolReleasedInput || n == param::kToolClampedInput;
        const bool sensor = std::find(std::begin(sensors), std::end(sensors), n) != std::end(sensors);
        if (sensor && !(drawbar && device) && std::find(linked.begin(), linked.end(), n) == linked.end()) {
            out.unsupported.push_back(params::inputName(input->pin) + " (" + function.nameEn + ", param " + std::to_string(n) +
                                      ") is wired but nothing in the simulation moves it (its output is not wired): "
                                      "a macro waiting for it stops with sensor_timeout");
        }
        const bool alarmOrLimit = (n >= 500 && n <= 542) || (n >= 635 && n <= 650);
        if (alarmOrLimit) {
            neverActive += (neverActive.empty() ? "" : ", ") + std::string(function.nameEn) + " " +
                           params::inputName(input->pin);
        }
    }
    if (!neverActive.empty()) {
        out.unsupported.push_back("wired but not simulated (the simulation never drives them; they read 0): " +
                                  neverActive);
    }
    static constexpr const char* axes[] = {"X", "Y", "Z"};
    for (int axis = 0; axis < 3; ++axis) {
        if (!params::wiredInput(p, param::kHomeSwitchX + 3 * axis)) {
            out.unsupported.push_back(std::string("no home switch is wired for ") + axes[axis] + " (param " +
                                      std::to_string(param::kHomeSwitchX + 3 * axis) + "): 回零 cannot home it");
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
