#include "ui/session/ProgramPreviews.h"

#include <QMetaObject>
#include <QPointer>

namespace m350::ui {

ProgramPreviews::ProgramPreviews(bool waitForBuilds, std::function<void()> ready)
    : waitForBuilds_(waitForBuilds), ready_(std::move(ready)) {}

// The jobs go first (each cancels and joins its thread): nothing is posted to this object after.
ProgramPreviews::~ProgramPreviews() {
    program_.job.reset();
    simulation_.job.reset();
}

void ProgramPreviews::request(Slot slot, const config::MachineConfig& config, const QString& path, int tool) {
    Entry& e = entry(slot);
    e.job.reset();
    const unsigned generation = ++e.generation;
    if (e.shown.file != path) {
        e.shown.preview.reset(); // another program's path is never shown under this one's name
    }
    e.shown.file = path;
    e.shown.building = true;
    if (waitForBuilds_) {
        PreviewJob job(config, path.toStdString(), tool, nullptr);
        job.wait();
        take(slot, generation, job.result(), false);
        return;
    }
    QPointer<ProgramPreviews> self(this);
    e.job = std::make_unique<PreviewJob>(config, path.toStdString(), tool, [self, slot, generation](auto built) {
        // on the job's thread: hand the result to the worker's
        QMetaObject::invokeMethod(
            self, [self, slot, generation, built] {
                if (self) {
                    self->take(slot, generation, built, true);
                }
            },
            Qt::QueuedConnection);
    });
}

void ProgramPreviews::clear(Slot slot) {
    Entry& e = entry(slot);
    e.job.reset();
    ++e.generation;
    e.shown = {};
}

void ProgramPreviews::take(Slot slot, unsigned generation, std::shared_ptr<const preview::Preview> built, bool announce) {
    Entry& e = entry(slot);
    if (generation != e.generation) {
        return; // a newer request replaced the build that made it
    }
    e.shown.preview = std::move(built);
    e.shown.building = false;
    if (announce && ready_) {
        ready_();
    }
}

} // namespace m350::ui
