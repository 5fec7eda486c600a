#include "ui/panel/PanelStateJson.h"

#include "ui/panel/PanelMode.h"

#include <QJsonArray>

namespace m350::ui {

namespace {

QJsonObject axes(const machine::Axes& position) {
    QJsonObject out;
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        out[QString(QChar(machine::kAxisNames[static_cast<std::size_t>(axis)]))] =
            std::round(position(axis) * 1e4) / 1e4;
    }
    return out;
}

template <std::size_t N> QJsonArray levels(const std::array<int, N>& values) {
    QJsonArray out;
    for (int v : values) {
        out.append(v);
    }
    return out;
}

const char* runName(controller::PanelStatus::Run run) {
    switch (run) {
    case controller::PanelStatus::Run::Idle: return "idle";
    case controller::PanelStatus::Run::Running: return "running";
    case controller::PanelStatus::Run::Hold: return "hold";
    case controller::PanelStatus::Run::Finished: return "finished";
    case controller::PanelStatus::Run::Alarm: return "alarm";
    case controller::PanelStatus::Run::EStop: return "estop";
    }
    return "";
}

} // namespace

QJsonObject panelStateJson(const PanelSnapshot& snapshot) {
    const controller::PanelStatus& s = snapshot.status;
    QJsonObject out;
    out["mode"] = PanelText::modeKey(displayedMode(snapshot));
    out["state"] = PanelText::stateKey(displayedState(snapshot));
    out["run"] = runName(s.run);
    out["time"] = std::round(s.time * 1000.0) / 1000.0;
    out["machine"] = axes(s.machine);
    out["work"] = axes(s.work);
    QJsonArray homed;
    for (bool h : s.homed) {
        homed.append(h);
    }
    out["homed"] = homed;
    out["tool"] = s.tool;
    out["tool_unsure"] = s.toolUnsure.has_value();
    out["status_message"] = QString::fromStdString(s.message);
    if (s.alarm) {
        out["alarm"] = QJsonObject{{"code", QString::fromLatin1(alarmKey(s.alarm->code).data(),
                                                                static_cast<qsizetype>(alarmKey(s.alarm->code).size()))},
                                   {"message", QString::fromStdString(s.alarm->message)},
                                   {"file", QString::fromStdString(s.alarm->file)},
                                   {"line", static_cast<int>(s.alarm->line)},
                                   {"column", static_cast<int>(s.alarm->column)}};
    } else {
        out["alarm"] = QJsonValue::Null;
    }
    out["inputs"] = levels(s.inputs);
    out["outputs"] = levels(s.outputs);
    out["feed_override"] = s.feedOverride;
    out["spindle_override"] = s.spindleOverride;
    out["spindle_rpm"] = s.spindleRpm;
    out["guide"] = s.guide;
    out["guide_override"] = s.guideOverride;
    out["program"] = snapshot.programFile;
    out["error"] = snapshot.lastError;
    if (s.dialog) {
        out["dialog"] = QString::fromStdString(*s.dialog);
    }
    return out;
}

} // namespace m350::ui
