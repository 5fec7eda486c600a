// The settings side of the session: parameters saved to the machine folder, the #50-#499 view and
// the user level the status line shows.
#include "ui/session/SessionWorker.h"

#include "core/controller/Controller.h"
#include "core/controller/ToolTableSave.h"
#include "ui/i18n/Language.h"

#include <cmath>
#include <limits>

namespace m350::ui {

namespace {

constexpr int kFirstUserVariable = 50;
constexpr int kLastUserVariable = 499;

} // namespace

bool SessionWorker::saveParameters(const std::map<int, double>& values) {
    if (folder_.path().empty()) {
        return true; // a machine built in memory (tests of the core) has no folder to keep
    }
    if (auto error = controller::saveParameters(*controller_, folder_, values)) { // with tool.tbl when due
        refuse(tr("File save failed!", "msg 907") + QStringLiteral(" ") + QString::fromStdString(error->in(Language::messageLanguage())));
        return false;
    }
    for (auto [number, value] : values) {
        kept_.set(number, value);
    }
    return true;
}

// What a run writes into parameters stays, as on the controller: a tool's Z offset from 对刀
// (params 930-945, 973-992), the setter's taught position (135-137), M30's counters. When a run
// stops, the parameters it changed go into params.toml (tool.tbl is kept by keepToolTable).
void SessionWorker::keepParametersTheRunChanged() {
    std::map<int, double> changed;
    for (int number = 0; number < params::ParameterTable::kCount; ++number) {
        const double now = controller_->parameter(number);
        if (now != kept_.get(number)) {
            changed[number] = now;
        }
    }
    if (!changed.empty()) {
        saveParameters(changed);
    }
}

void SessionWorker::setParameters(const std::map<int, double>& values) {
    lastError_.clear();
    for (auto [number, value] : values) {
        if (!controller_->setParameter(number, value)) {
            refuse(tr("Parameter %1: invalid value").arg(number));
            return;
        }
    }
    if (!saveParameters(values)) {
        return;
    }
    publish();
}

void SessionWorker::watchVariables(bool on) {
    watchVariables_ = on;
    publish();
}

void SessionWorker::watchScene(bool on) {
    if (on == watchScene_) {
        return;
    }
    watchScene_ = on;
    if (!on) {
        scene_.reset();
    }
    publish();
}

QVector<double> SessionWorker::userVariables() {
    QVector<double> values;
    values.reserve(kLastUserVariable - kFirstUserVariable + 1);
    for (int number = kFirstUserVariable; number <= kLastUserVariable; ++number) {
        macro::Value v = controller_->variable(number);
        values.push_back(v.vacant ? std::numeric_limits<double>::quiet_NaN() : v.number);
    }
    return values;
}

void SessionWorker::setUserLevel(params::UserLevel level) {
    userLevel_ = level;
    controller_->setUserLevel(level);
    publish();
}

} // namespace m350::ui
