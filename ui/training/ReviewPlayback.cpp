#include "ui/training/ReviewPlayback.h"

#include "ui/panel/MainWindow.h"
#include "ui/session/MachineSession.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace m350::ui {

namespace {

constexpr double kReviewFrame = 1.0 / 60.0;

} // namespace

ReviewPlayback::ReviewPlayback(MainWindow& window, MachineSession& session, std::vector<OperatorAction> actions,
                               std::vector<ReplayPlace> places, QString path)
    : window_(window), session_(session), actions_(std::move(actions)), places_(std::move(places)), path_(std::move(path)) {
    places_.resize(actions_.size());
}

ReviewPlayback::Block ReviewPlayback::blockOf(const PanelSnapshot& snapshot) {
    return Block{snapshot.status.file, snapshot.status.line, snapshot.status.blocks};
}

ReviewPlayback::Block ReviewPlayback::block() const {
    const SnapshotPtr latest = session_.latest();
    return latest ? blockOf(*latest) : Block{};
}

double ReviewPlayback::play(double seconds) {
    const double budget = seconds + owed_;
    const double passed = run(budget, {});
    owed_ = finished() ? 0.0 : std::max(0.0, budget - passed);
    return passed;
}

bool ReviewPlayback::stepBlock() {
    const Block from = block();
    run(end() - now_ + 1.0, [this, &from] { return block() != from; });
    owed_ = 0.0;
    return block() != from;
}

// As playReplay: frames of 1/60 s up to the next action's time, the last one ending on it; quiet
// stretches at once (the machine sees the same frames, the panel only the last); the action
// through the dispatcher once its time has come.
double ReviewPlayback::run(double budget, const std::function<bool()>& stop) {
    double passed = 0.0;
    window_.holdRendering(true); // the panel shows the last frame of a call, not each of them
    // and nothing paints before the call ends: at 50x a tick is 50 frames, each of which painted
    // the review's views (half of a review's CPU time)
    QWidget* screen = window_.window();
    const bool painting = screen->updatesEnabled();
    screen->setUpdatesEnabled(false);
    while (!finished()) {
        const OperatorAction& action = actions_[next_];
        if (now_ + 1e-9 >= action.t) {
            playNext();
            if (stop && stop()) {
                break;
            }
            continue;
        }
        const double room = budget - passed;
        const double frame = std::min(kReviewFrame, action.t - now_);
        if (frame > room + 1e-9) {
            break;
        }
        double step = 0.0;
        if (!stop) {
            // whole frames, or every frame up to the action when they all fit
            const double reach = action.t - now_ <= room + 1e-9
                                     ? action.t - now_
                                     : std::floor((room + 1e-9) / kReviewFrame) * kReviewFrame;
            step = session_.advanceWhileQuiet(reach, true);
        }
        if (step <= 0.0) {
            session_.advance(frame);
            step = frame;
        }
        now_ += step;
        passed += step;
        QCoreApplication::processEvents();
        if (stop && stop()) {
            break;
        }
    }
    window_.holdRendering(false);
    screen->setUpdatesEnabled(painting);
    settle(session_);
    return passed;
}

void ReviewPlayback::playNext() {
    const OperatorAction& action = actions_[next_];
    if (QString refused = refusedReplayLoad(window_, action, path_, places_[next_]); !refused.isEmpty()) {
        error_ = refused;
        return;
    }
    window_.renderHeld(); // the action may read what the page shows
    window_.dispatcher().dispatch(action);
    ++next_;
    if (action.kind != OperatorAction::Kind::Wait) {
        settle(session_);
    }
}

} // namespace m350::ui
