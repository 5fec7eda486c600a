#include "core/controller/UnattendedOperator.h"

#include <cstdio>
#include <string>

namespace m350::controller {

namespace {

std::string unattendedSeconds(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", seconds);
    return text;
}

} // namespace

UnattendedOperator::UnattendedOperator(const RunSettings& settings, double runStartedAt, bool running)
    : startedAt_(runStartedAt) {
    if (running && settings.pauseAt) {
        pauseAt_ = runStartedAt + *settings.pauseAt;
    }
    if (running && settings.estopAt) {
        estopAt_ = runStartedAt + *settings.estopAt;
    }
}

UnattendedOperator::Press UnattendedOperator::next() {
    if (estopAt_ && (!pauseAt_ || *estopAt_ < *pauseAt_)) {
        const Press press{Key::EStop, *estopAt_};
        estopAt_.reset();
        return press;
    }
    if (pauseAt_) {
        const Press press{Key::Pause, *pauseAt_};
        pauseAt_.reset();
        return press;
    }
    return {};
}

Message UnattendedOperator::pressed(const Press& press, const TraceSource& where) const {
    return message(press.key == Key::EStop ? "notice_estop_pressed" : "notice_pause_pressed",
                   {unattendedSeconds(press.at - startedAt_), where.file, std::to_string(where.line)});
}

bool UnattendedOperator::startAfterHold(const machine::Axes& at) {
    // `N1 M00` / `GOTO1` holds forever and costs no virtual time: holds over and over with the
    // machine standing still wait on an operator this run has not got
    idleHolds_ = heldAt_ && (*heldAt_ - at).cwiseAbs().maxCoeff() == 0.0 ? idleHolds_ + 1 : 1;
    heldAt_ = at;
    return idleHolds_ <= kMostIdleHolds;
}

Message UnattendedOperator::loopWords(const TraceSource& where) const {
    return message("operator_loop", {where.file, std::to_string(where.line), std::to_string(kMostIdleHolds)});
}

} // namespace m350::controller
