// The machine view's side of the session: the previews the snapshots carry.
#include "ui/session/ProgramPreviews.h"
#include "ui/session/SessionWorker.h"

namespace m350::ui {

ProgramPreviews& SessionWorker::previews() {
    if (!previews_) {
        previews_ = std::make_unique<ProgramPreviews>(options_.clock == MachineSession::Clock::Manual, [this] { publish(); });
    }
    return *previews_;
}

} // namespace m350::ui
