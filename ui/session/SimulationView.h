#pragma once

#include "core/preview/MachineScene.h"

#include <QString>

#include <cstdint>
#include <memory>
#include <vector>

namespace m350::ui {

// One point of a simulated tool path, in machine coordinates (mm).
struct PathPoint {
    float x = 0.0F;
    float y = 0.0F;
    float z = 0.0F;
    bool rapid = false; // the move that ends here is a G00
};

// The path so far, shared by every snapshot without copying it: full chunks never change again,
// so a snapshot takes their pointers and copies only the chunk still growing.
struct SimulationPath {
    static constexpr std::size_t kChunk = 4096;
    std::vector<std::shared_ptr<const std::vector<PathPoint>>> chunks; // the last one may be partial
    std::size_t size = 0;

    template <class F> void forEach(std::size_t from, F&& f) const {
        std::size_t index = 0;
        for (const auto& chunk : chunks) {
            if (index + chunk->size() > from) {
                for (std::size_t i = from > index ? from - index : 0; i < chunk->size(); ++i) {
                    f((*chunk)[i]);
                }
            }
            index += chunk->size();
        }
    }
};

// What the Program page's 仿真 shows: a run of the file on a second controller in the worker
// thread, which never moves the machine the panel drives.
struct SimulationView {
    enum class Run : std::uint8_t { Off, Running, Finished, Alarm };
    Run run = Run::Off;
    QString file;       // the file simulated
    QString runningFile;    // the file of the block being executed (the program or a macro library)
    std::uint32_t line = 0; // and its line
    double time = 0.0;  // virtual seconds into the simulated run
    double speed = 1.0; // virtual seconds per wall second; 0 = as fast as the core goes
    std::uint64_t blocks = 0;
    std::uint64_t moves = 0; // moves the simulated run has made
    QString alarm;      // file:line:col: message of the alarm that ended it
    SimulationPath path;
    // The simulated machine's scene (tools, magazine, offsets as the simulated run leaves them):
    // a new object only when it changed; null while Off.
    std::shared_ptr<const preview::MachineScene> scene;
    bool active() const { return run != Run::Off; }
};

} // namespace m350::ui
