#include "ui/session/SimulationSide.h"

#include "ui/session/ProgramPreviews.h"
#include "ui/session/SimulationRun.h"

#include <limits>

namespace m350::ui {

SimulationSide::SimulationSide(bool manualClock, std::function<void()> ready)
    : manualClock_(manualClock), ready_(std::move(ready)) {}

SimulationSide::~SimulationSide() = default;

ProgramPreviews& SimulationSide::previews() {
    if (!previews_) {
        previews_ = std::make_unique<ProgramPreviews>(manualClock_, ready_);
    }
    return *previews_;
}

std::optional<QString> SimulationSide::start(const config::MachineConfig& config, const QString& path, int tool, double speed) {
    simulation_.reset();
    QString error;
    simulation_ = SimulationRun::start(config, path, tool, speed, &error);
    if (!simulation_) {
        previews().clear(ProgramPreviews::Slot::Simulation);
        return error;
    }
    previews().request(ProgramPreviews::Slot::Simulation, config, path, tool);
    return std::nullopt;
}

void SimulationSide::setSpeed(double speed) {
    if (simulation_) {
        simulation_->setSpeed(speed);
    }
}

void SimulationSide::stop() { simulation_.reset(); }

bool SimulationSide::running() const { return simulation_ && simulation_->running(); }

// A simulation at speed 0 runs as fast as the core goes: with the wall clock for most of a
// frame, with a manual clock to its end at once.
void SimulationSide::advance(double seconds) {
    if (!running()) {
        return;
    }
    constexpr long long kBudgetNs = 10'000'000; // of the 16.7 ms frame
    if (simulation_->speed() > 0.0) {
        simulation_->advance(seconds * simulation_->speed());
    } else if (manualClock_) {
        simulation_->advance(std::numeric_limits<double>::infinity());
    } else {
        simulation_->runFor(kBudgetNs);
    }
}

void SimulationSide::previewLoaded(const config::MachineConfig& config, const QString& path, int tool) {
    previews().request(ProgramPreviews::Slot::Program, config, path, tool);
}

void SimulationSide::clearLoaded() { previews().clear(ProgramPreviews::Slot::Program); }

void SimulationSide::finish() { previews_.reset(); }

void SimulationSide::fill(PanelSnapshot& snapshot) const {
    if (simulation_) {
        snapshot.simulation = simulation_->view();
    }
    if (previews_) {
        snapshot.programPreview = previews_->shown(ProgramPreviews::Slot::Program);
        snapshot.simulationPreview = previews_->shown(ProgramPreviews::Slot::Simulation);
    }
}

} // namespace m350::ui
