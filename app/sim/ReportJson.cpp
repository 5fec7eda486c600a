#include "app/sim/ReportJson.h"

#include "core/controller/AxesJson.h"

#include "core/common/Alarm.h"

#include <algorithm>

namespace m350::sim {

namespace {

// The message's id and arguments (said in English, as `message` is), only for a message of the
// table: the other objects keep the contract's keys as they were.
void addMessageId(nlohmann::json& object, const std::string& id, const std::vector<std::string>& arguments) {
    if (id.empty()) {
        return;
    }
    object["message_id"] = id;
    nlohmann::json said = nlohmann::json::array();
    for (const std::string& argument : arguments) {
        said.push_back(argumentIn(argument, MessageLanguage::English));
    }
    object["message_arguments"] = std::move(said);
}

nlohmann::json firstError(const std::vector<gcode::Diagnostic>& diagnostics) {
    for (const gcode::Diagnostic& d : diagnostics) {
        if (d.severity == gcode::Severity::Error && d.kind == gcode::DiagnosticKind::Syntax) {
            nlohmann::json error{{"code", d.unreadable ? "file_error" : "syntax_error"}, {"message", d.message}, {"file", d.file}, {"line", d.line},
                                 {"column", d.column}};
            addMessageId(error, d.messageId, d.messageArguments);
            return error;
        }
    }
    return nullptr;
}

} // namespace

nlohmann::json diagnosticsJson(const std::vector<gcode::Diagnostic>& diagnostics) {
    nlohmann::json list = nlohmann::json::array();
    for (const gcode::Diagnostic& d : diagnostics) {
        const char* kind = d.kind == gcode::DiagnosticKind::Syntax ? "syntax"
                           : d.kind == gcode::DiagnosticKind::Flow ? "flow"
                                                                   : "lint";
        list.push_back({{"file", d.file},
                        {"line", d.line},
                        {"column", d.column},
                        {"severity", d.severity == gcode::Severity::Error ? "error" : "warning"},
                        {"kind", kind},
                        {"message", d.message}});
        if (d.omitted > 0) {
            list.back()["omitted"] = d.omitted;
        }
        addMessageId(list.back(), d.messageId, d.messageArguments);
    }
    return list;
}

nlohmann::json reportJson(const controller::RunReport& report, controller::Controller& controller,
                          const std::vector<int>& printVariables) {
    nlohmann::json j;
    switch (report.status) {
    case controller::RunStatus::Ok: j["status"] = "ok"; break;
    case controller::RunStatus::Alarm: j["status"] = "alarm"; break;
    case controller::RunStatus::Error: j["status"] = "error"; break;
    }
    if (report.alarm) {
        const Alarm& a = *report.alarm;
        j["alarm"] = {{"code", std::string(alarmKey(a.code))}, {"message", a.message}, {"file", a.file},
                      {"line", a.line}, {"column", a.column}};
        addMessageId(j["alarm"], a.messageId, a.messageArguments);
    } else if (report.status == controller::RunStatus::Error) {
        j["alarm"] = firstError(report.diagnostics);
    } else {
        j["alarm"] = nullptr;
    }
    nlohmann::json vars = nlohmann::json::object();
    for (int n : printVariables) {
        macro::Value v = controller.variable(n);
        vars[std::to_string(n)] = v.vacant ? nlohmann::json(nullptr) : nlohmann::json(v.number);
    }
    j["vars"] = vars;
    j["machine"] = controller::axesJson(report.machine);
    j["work"] = controller::axesJson(report.work);
    j["tool"] = report.tool;
    if (!report.warnings.empty()) {
        nlohmann::json warnings = nlohmann::json::array();
        for (const Alarm& w : report.warnings) {
            warnings.push_back({{"message", w.message}, {"message_id", w.messageId}, {"arguments", w.messageArguments}});
        }
        j["warnings"] = warnings;
    }
    if (report.toolUnsure) {
        // the controller does not know which tool the spindle holds (a stop in a change)
        j["tool_unsure"] = {{"message", report.toolUnsure->message},
                            {"message_id", report.toolUnsure->messageId},
                            {"arguments", report.toolUnsure->messageArguments}};
    }
    nlohmann::json pockets = nlohmann::json::object();
    for (auto [pocket, tool] : report.pockets) {
        pockets[std::to_string(pocket)] = tool;
    }
    j["pockets"] = pockets;
    if (!report.fallenTools.empty()) { // only then: the contract's keys stay as they were
        nlohmann::json fallen = nlohmann::json::array();
        for (const devices::FallenTool& f : report.fallenTools) {
            fallen.push_back({{"tool", f.tool}, {"at", {{"X", f.at.x()}, {"Y", f.at.y()}, {"Z", f.at.z()}}}});
        }
        j["fallen_tools"] = fallen;
    }
    j["outputs"] = report.outputs;
    j["messages"] = report.messages;
    if (std::any_of(report.messageWords.begin(), report.messageWords.end(), [](const Message& m) { return !m.id.empty(); })) {
        // only then: the contract's keys stay as they were; null for a line of the program's own words
        nlohmann::json ids = nlohmann::json::array();
        for (const Message& m : report.messageWords) {
            if (m.id.empty()) {
                ids.push_back(nullptr);
                continue;
            }
            nlohmann::json said = nlohmann::json::object();
            addMessageId(said, m.id, m.arguments);
            ids.push_back(std::move(said));
        }
        j["message_ids"] = std::move(ids);
    }
    if (report.messagesOmitted > 0) { // only then: the contract's keys stay as they were
        j["messages_omitted"] = report.messagesOmitted;
    }
    j["sim_time_s"] = report.simTime;
    j["diagnostics"] = diagnosticsJson(report.diagnostics);
    return j;
}

// Every key of the contract is present even when nothing ran, so scripts can read any of them.
nlohmann::json errorJson(const std::string& code, const std::string& message, const std::string& file, int line,
                         int column) {
    return {{"status", "error"},
            {"alarm", {{"code", code}, {"message", message}, {"file", file}, {"line", line}, {"column", column}}},
            {"vars", nlohmann::json::object()},
            {"machine", controller::axesJson(machine::Axes::Zero())},
            {"work", controller::axesJson(machine::Axes::Zero())},
            {"tool", 0},
            {"pockets", nlohmann::json::object()},
            {"outputs", std::vector<int>(machine::kOutputCount, 0)},
            {"messages", nlohmann::json::array()},
            {"sim_time_s", 0.0},
            {"diagnostics", nlohmann::json::array()}};
}

std::string dump(const nlohmann::json& j) {
    return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

} // namespace m350::sim
