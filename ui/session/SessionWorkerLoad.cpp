// The breakage monitor's side of the session: the spindle load view the snapshots carry.
#include "ui/session/SessionWorker.h"

#include "core/controller/Controller.h"

namespace m350::ui {

void SessionWorker::keepSpindleLoad(int tool) {
    const controller::SpindleLoadWatch& watch = controller_->toolBreakage().spindleLoad();
    if (!watch.model()) {
        return;
    }
    if (spindleLoad_ && spindleLoad_->taken == watch.monitor().taken() && spindleLoad_->tool == tool) {
        return;
    }
    spindleLoad_ = std::make_shared<const controller::SpindleLoadView>(
        watch.view(tool, controller_->dialect().id == gcode::DialectId::Fanuc));
}

} // namespace m350::ui
