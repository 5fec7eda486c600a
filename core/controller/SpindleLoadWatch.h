#pragma once

#include "core/controller/SpindleLoadView.h"
#include "core/machine/SimulatedMachine.h"
#include "core/machine/SpindleLoadModel.h"
#include "core/machine/ToolWorld.h"
#include "core/tools/SpindleLoadMonitor.h"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace m350::controller {


// Samples the simulated spindle load as virtual time passes (every move, dwell and switch the
// machine reports) and feeds the breakage monitor: the PMC side of the FANUC article. The load
// comes from the machine world (SpindleLoadModel over the tools as they really are, ToolWorld);
// the monitor sees only what a control sees: the register's value (load % x 100).
class SpindleLoadWatch {
public:
    struct Anomaly {
        double time = 0.0;
        Message message;
    };

    void setModel(std::optional<machine::SpindleLoadModel> model) { model_ = std::move(model); }
    const std::optional<machine::SpindleLoadModel>& model() const { return model_; }
    tools::SpindleLoadMonitor& monitor() { return monitor_; }
    const tools::SpindleLoadMonitor& monitor() const { return monitor_; }

    // Takes the samples due up to the machine's clock; the first anomaly, if one came. `event` is
    // the machine event that just happened (its feed applies while its move lasts).
    std::optional<Anomaly> sampleUpTo(const machine::SimulatedMachine& machine, const machine::MachineEvent& event,
                                      const machine::ToolWorld& world, int tool);
    // Starts sampling from virtual time t (a new controller, a machine whose clock jumped).
    void startAt(double t) { next_ = t; }
    // The register the macros read (FANUC #1032, M350 #2990): the last sample's load % x 100.
    std::uint16_t reg() const { return reg_; }
    // The page's picture with `tool` in the spindle; `fanuc` picks the register's variable.
    SpindleLoadView view(int tool, bool fanuc) const;

private:
    tools::LoadSample measure(const machine::SimulatedMachine& machine, const machine::MachineEvent& event,
                              const machine::ToolWorld& world, int tool, double t) const;
    std::optional<machine::SpindleLoadModel> model_;
    tools::SpindleLoadMonitor monitor_;
    double next_ = 0.0;
    std::uint16_t reg_ = 0;
};

} // namespace m350::controller
