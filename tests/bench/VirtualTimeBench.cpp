// How fast virtual time runs: a full tool change (T2 from T1 on the default machine, about 20 s of
// machine time with the spindle coasting, the clamp cylinder and the sensor waits) run headless.
// Reported as virtual seconds per wall second (target >= 10,000x: a 20 s change in under 2 ms).
// And what an MDI line costs, with the machine's libraries parsed at every line or joined.
#include "core/config/MachineConfig.h"
#include "core/controller/Controller.h"

#include <benchmark/benchmark.h>

#include <string>
#include <variant>

namespace {

using namespace m350;

config::MachineConfig defaultMachine() {
    auto loaded = config::loadMachineFolder(config::bundledMachinesDirectory() + "/" + config::kDefaultMachine);
    return std::get<config::MachineConfig>(std::move(loaded));
}

void ToolChange(benchmark::State& state) {
    const config::MachineConfig machine = defaultMachine();
    double virtualSeconds = 0.0;
    for (auto _ : state) {
        controller::Controller controller(machine, {});
        controller.loadMdi({"M3 S12000", "T2"});
        controller::RunReport report = controller.run();
        if (report.status != controller::RunStatus::Ok || report.tool != 2) {
            state.SkipWithError("the tool change did not end with tool 2 in the spindle");
            return;
        }
        virtualSeconds += report.simTime;
    }
    state.counters["virtual_s_per_change"] = virtualSeconds / static_cast<double>(state.iterations());
    state.counters["virtual_s_per_wall_s"] = benchmark::Counter(virtualSeconds, benchmark::Counter::kIsRate);
}

// An MDI line typed and run on the default machine, as the panel's MDI page runs each line: loaded
// with the machine's libraries (slib-g.nc, slib-m.nc, slib-probe.nc) and run. Argument 1 joins the
// libraries parsed once (RunSettings::reuseParsedLibraries), 0 parses them at every line.
void MdiLine(benchmark::State& state) {
    controller::RunSettings settings;
    settings.reuseParsedLibraries = state.range(0) != 0;
    controller::Controller controller(defaultMachine(), settings);
    bool forth = true;
    for (auto _ : state) {
        if (!controller.loadMdi({forth ? "G91 G1 X0.05 F1000" : "G91 G1 X-0.05 F1000"})) {
            state.SkipWithError("the MDI line did not load");
            return;
        }
        controller.run();
        forth = !forth;
    }
}

} // namespace

BENCHMARK(ToolChange)->Unit(benchmark::kMicrosecond);
BENCHMARK(MdiLine)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
