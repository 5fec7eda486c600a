#include "ui/actions/ActionRecorder.h"

#include <QJsonDocument>

#include <cmath>

namespace m350::ui {

bool ActionRecorder::start(const QString& path, QString* error) {
    stop();
    file_.setFileName(path);
    if (!file_.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text)) {
        if (error) {
            *error = QStringLiteral("%1: cannot write: %2").arg(path, file_.errorString());
        }
        return false;
    }
    return true;
}

void ActionRecorder::stop() {
    if (file_.isOpen()) {
        file_.close();
    }
}

void ActionRecorder::record(const OperatorAction& action) {
    if (!file_.isOpen()) {
        return;
    }
    OperatorAction stamped = action;
    // the clock as it is, not rounded to the millisecond: a handwheel turn lasts its `seconds` up to
    // the next one, and a gap made longer by rounding would let the 试切 override ramp down between
    // turns in the replay (it ramps down five times faster than up: the run would crawl)
    stamped.t = clock_();
    file_.write(QJsonDocument(stamped.toJson()).toJson(QJsonDocument::Compact));
    file_.write("\n");
    file_.flush(); // a session can end at any moment; what was done so far stays in the file
}

} // namespace m350::ui
