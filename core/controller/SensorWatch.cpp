#include "core/controller/SensorWatch.h"

namespace m350::controller {

SensorWatch::Verdict SensorWatch::read(int pin, int level, double now, const gcode::SourceLocation& where,
                                       double timeout) {
    bool same = wait_ && wait_->pin == pin && wait_->level == level && wait_->where.file == where.file &&
                wait_->where.line == where.line;
    if (!same) {
        wait_ = Wait{pin, level, now, where};
        announced_ = false;
        return Verdict::Reading;
    }
    double waited = now - wait_->since;
    if (waited >= timeout) {
        return Verdict::TimedOut;
    }
    if (!announced_ && waited > 0.0) {
        announced_ = true;
        return Verdict::WaitBegins;
    }
    return announced_ ? Verdict::Waiting : Verdict::Reading;
}

} // namespace m350::controller
