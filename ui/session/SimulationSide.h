#pragma once

#include "ui/session/PanelSnapshot.h"

#include <QString>

#include <functional>
#include <memory>
#include <optional>

namespace m350::config {
struct MachineConfig;
}

namespace m350::ui {

class ProgramPreviews;
class SimulationRun;

// What the session runs beside the machine: the Program page's 仿真 (a SimulationRun of a file on
// a copy of the machine) and the machine view's previews of the loaded and the simulated program
// (built in a thread of their own, made on first use). A manual clock (replays, tests) waits for
// each preview and runs a fast simulation to its end at once, so that a replay is deterministic.
class SimulationSide {
public:
    // `ready`: a preview finished (the session publishes it).
    SimulationSide(bool manualClock, std::function<void()> ready);
    ~SimulationSide();

    // Starts a simulation of `path` at `speed` (0: as fast as the core goes); why not, if it cannot.
    std::optional<QString> start(const config::MachineConfig& config, const QString& path, int tool, double speed);
    void setSpeed(double speed);
    void stop();
    bool running() const;
    void advance(double seconds); // one frame of the session's clock
    // The preview of the program loaded into the machine; none after a failed load.
    void previewLoaded(const config::MachineConfig& config, const QString& path, int tool);
    void clearLoaded();
    void finish(); // cancels a preview build under way
    void fill(PanelSnapshot& snapshot) const; // the simulation's view and both previews

private:
    ProgramPreviews& previews();

    bool manualClock_;
    std::function<void()> ready_;
    std::unique_ptr<SimulationRun> simulation_;
    std::unique_ptr<ProgramPreviews> previews_;
};

} // namespace m350::ui
