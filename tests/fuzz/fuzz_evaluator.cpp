// libFuzzer target: MDI lines run on a simulated controller of a bundled machine. The first byte
// picks the machine ('0' m350-linear16, '1' fanuc-ts27r, then round again); the rest is the
// program. A run is bounded by a short virtual-time limit, so an input that runs for long in wall
// time (the runaway guard failing) shows up as a libFuzzer timeout.
#include "core/check/StaticCheck.h"
#include "core/config/MachineConfig.h"
#include "core/controller/Controller.h"
#include "core/gcode/SourceText.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <variant>

namespace {

constexpr std::array<const char*, 2> kMachines{"m350-linear16", "fanuc-ts27r"};

// Loaded once: each input runs on a fresh controller made from a copy.
const m350::config::MachineConfig& machine(std::size_t index) {
    static const std::array<m350::config::MachineConfig, kMachines.size()> loaded = [] {
        std::array<m350::config::MachineConfig, kMachines.size()> configs;
        for (std::size_t i = 0; i < kMachines.size(); ++i) {
            auto folder = m350::config::loadMachineFolder(std::string(M350_MACHINES_DIR) + "/" + kMachines[i]);
            if (auto* error = std::get_if<m350::config::ConfigError>(&folder)) {
                std::fprintf(stderr, "%s: %s\n", error->where().c_str(), error->message.english().c_str());
                std::abort();
            }
            configs[i] = std::get<m350::config::MachineConfig>(std::move(folder));
        }
        return configs;
    }();
    return loaded[index];
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return 0;
    }
    const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
    auto decoded = m350::gcode::decodeSource("MDI", bytes);
    const auto* source = std::get_if<m350::gcode::SourceText>(&decoded);
    if (source == nullptr) {
        return 0;
    }
    m350::controller::RunSettings settings;
    settings.maxSimTime = 30.0; // virtual seconds: long enough for a tool change
    settings.sensorTimeout = 2.0;
    const std::size_t machineIndex = static_cast<std::uint8_t>(data[0] - '0') % kMachines.size();
    m350::controller::Controller controller(machine(machineIndex), settings);
    if (controller.loadMdi({std::string(source->text)})) {
        const m350::config::MachineConfig config = controller.config();
        m350::check::StaticCheck(controller.program(), *config.dialect, config.callCodes).findings();
        controller.run();
    }
    return 0;
}
