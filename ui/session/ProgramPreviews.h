#pragma once

#include "ui/session/PreviewJob.h"
#include "ui/session/PreviewShown.h"

#include <QObject>

#include <functional>
#include <memory>

namespace m350::ui {

// The previews the machine view draws: the loaded program's and the 仿真 file's, each built on
// a thread of its own when asked for (a newer request cancels the build it replaces). Lives in the
// session's worker thread; a finished build is taken in there, then `ready` is called so that the
// worker publishes it.
class ProgramPreviews : public QObject {
    Q_OBJECT
public:
    enum class Slot { Program, Simulation };

    // `waitForBuilds`: a manual clock's session (replays, tests) waits for each build, so what a
    // replay shows never depends on how fast the machine is.
    ProgramPreviews(bool waitForBuilds, std::function<void()> ready);
    ~ProgramPreviews() override;

    // Builds the preview of `path` on `config` with `tool` in the spindle at the start.
    void request(Slot slot, const config::MachineConfig& config, const QString& path, int tool);
    void clear(Slot slot);
    const PreviewShown& shown(Slot slot) const { return slot == Slot::Program ? program_.shown : simulation_.shown; }

private:
    struct Entry {
        PreviewShown shown;
        std::unique_ptr<PreviewJob> job;
        unsigned generation = 0;
    };
    Entry& entry(Slot slot) { return slot == Slot::Program ? program_ : simulation_; }
    void take(Slot slot, unsigned generation, std::shared_ptr<const preview::Preview> built, bool announce);

    bool waitForBuilds_;
    std::function<void()> ready_;
    Entry program_;
    Entry simulation_;
};

} // namespace m350::ui
