#pragma once

#include "ui/session/SimulationView.h"

#include "core/machine/MachineTypes.h"

#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace m350::config {
struct MachineConfig;
}
namespace m350::controller {
class Controller;
}

namespace m350::ui {

// 仿真: the file run on a controller of its own, built from the panel machine's configuration as
// it stands, in the session's worker thread. The panel's machine never moves. It draws the path
// from the machine events (arcs split into short chords) and answers what an operator would:
// a program stop (M00, G04 P-1) is resumed at once, a #1505 dialog gets Enter.
class SimulationRun : public machine::MachineObserver {
public:
    // Nullptr with `error` set when the file cannot be read or does not parse.
    static std::unique_ptr<SimulationRun> start(const config::MachineConfig& config, const QString& path,
                                                std::optional<int> tool, double speed, QString* error);
    ~SimulationRun() override;

    void setSpeed(double speed) { view_.speed = speed; }
    double speed() const { return view_.speed; }
    // Lets `seconds` of simulated time pass.
    void advance(double seconds);
    // As fast as the core goes, for about `wallNs` of wall time (or to the end).
    void runFor(long long wallNs);
    bool running() const { return view_.run == SimulationView::Run::Running; }
    // What the snapshot carries: shares the path's full chunks, copies the growing one.
    SimulationView view();

    void onMachineEvent(const machine::MachineEvent& event) override;

private:
    SimulationRun() = default;
    void add(const machine::Axes& at, bool rapid);
    void follow();

    std::unique_ptr<controller::Controller> controller_;
    SimulationView view_;
    std::vector<PathPoint> tail_;
    bool started_ = false;
};

} // namespace m350::ui
