#include "core/training/Verdict.h"

#include "core/files/MachineFileRead.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace m350::training {

namespace {

std::string shownNumber(double value) {
    char text[64];
    std::snprintf(text, sizeof text, "%.4f", value);
    std::string out = text;
    while (out.size() > 1 && out.back() == '0') {
        out.pop_back();
    }
    if (out.back() == '.') {
        out.pop_back();
    }
    return out == "-0" ? "0" : out;
}

std::string placeOf(const Alarm& alarm) {
    return alarm.file.empty() ? std::string() : alarm.file + ":" + std::to_string(alarm.line);
}

CheckTarget lineTarget(const Alarm& alarm) {
    if (alarm.file.empty()) {
        return {};
    }
    return {CheckTarget::Kind::Line, 0, alarm.file, static_cast<int>(alarm.line)};
}

// Line `line` (1-based) of a file, without its line end; nullopt when it has fewer lines.
std::optional<std::string> fileLine(const std::string& path, int line) {
    std::string text;
    if (files::readMachineFile(path, text)) {
        return std::nullopt;
    }
    std::istringstream lines(text);
    std::string current;
    for (int n = 1; std::getline(lines, current); ++n) {
        if (n == line) {
            while (!current.empty() && (current.back() == '\r' || current.back() == ' ' || current.back() == '\t')) {
                current.pop_back();
            }
            return current.substr(std::min(current.find_first_not_of(" \t"), current.size()));
        }
    }
    return std::nullopt;
}

std::string trimmed(const std::string& text) {
    const auto begin = text.find_first_not_of(" \t");
    const auto end = text.find_last_not_of(" \t\r");
    return begin == std::string::npos ? std::string() : text.substr(begin, end - begin + 1);
}

// A program line as the controller reads it: the code without its spaces (G53 Y#1309 F#1311 and
// G53Y#1309F#1311 are one block), the comment (from // or ( or ;) left out: a trainee who repairs
// the code with other spacing, or writes a comment of their own, has repaired it.
std::string codeOf(const std::string& line) {
    std::string code;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (c == '(' || c == ';' || (c == '/' && i + 1 < line.size() && line[i + 1] == '/')) {
            break;
        }
        if (c != ' ' && c != '\t' && c != '\r') {
            code += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        }
    }
    return code;
}

bool isOperatorAlarm(const Alarm& alarm) {
    return alarm.code == AlarmCode::OperatorReset || alarm.code == AlarmCode::EmergencyStop;
}

CheckResult evaluate(const Check& check, const AttemptFacts& facts) {
    CheckResult result;
    result.id = check.id;
    result.kind = check.kind;
    using K = Check::Kind;
    using Event = controller::RunEvents::Event;
    auto within = [&](double measured) {
        result.measured = shownNumber(measured);
        result.expected = shownNumber(check.expect) + (check.tolerance > 0 ? " ± " + shownNumber(check.tolerance) : "");
        result.passed = std::abs(measured - check.expect) <= check.tolerance + 1e-9;
    };
    switch (check.kind) {
    case K::SpindleTool:
        result.measured = "T" + std::to_string(facts.spindleTool);
        result.expected = "T" + shownNumber(check.expect);
        result.passed = facts.spindleTool == static_cast<int>(check.expect);
        result.target = {CheckTarget::Kind::Tool, static_cast<int>(check.expect), {}, 0};
        break;
    case K::PocketTool: {
        auto pocket = facts.pockets.find(check.number);
        const int tool = pocket == facts.pockets.end() ? 0 : pocket->second;
        result.measured = pocket == facts.pockets.end() ? "-" : "T" + std::to_string(tool);
        result.expected = "T" + shownNumber(check.expect);
        result.passed = pocket != facts.pockets.end() && tool == static_cast<int>(check.expect);
        result.target = {CheckTarget::Kind::Tool, static_cast<int>(check.expect), {}, 0};
        break;
    }
    case K::NoAlarm:
    case K::NoCrash: {
        result.passed = true;
        result.measured = "-";
        result.expected = "-";
        for (const Event& event : facts.events) {
            const bool counts = event.kind == Event::Kind::Alarm && !isOperatorAlarm(event.alarm) &&
                                (check.kind == K::NoAlarm || event.alarm.code == AlarmCode::Crash);
            if (counts) {
                result.passed = false;
                result.measured = std::string(alarmKey(event.alarm.code)) + " " + placeOf(event.alarm);
                result.measured = trimmed(result.measured);
                result.target = lineTarget(event.alarm);
                break;
            }
        }
        break;
    }
    case K::Alarm: {
        result.expected = check.code;
        result.measured = "-";
        for (const Event& event : facts.events) {
            if (event.kind == Event::Kind::Alarm && alarmKey(event.alarm.code) == check.code) {
                result.passed = true;
                result.measured = trimmed(check.code + " " + placeOf(event.alarm));
                break;
            }
        }
        break;
    }
    case K::Parameter: {
        auto value = facts.parameters.find(check.number);
        within(value == facts.parameters.end() ? NAN : value->second);
        result.target = {CheckTarget::Kind::Parameter, check.number, {}, 0};
        break;
    }
    case K::ToolOffset: {
        auto value = facts.toolOffsets.find(check.number);
        within(value == facts.toolOffsets.end() ? NAN : value->second);
        result.target = {CheckTarget::Kind::Tool, check.number, {}, 0};
        break;
    }
    case K::Variable: {
        auto value = facts.variables.find(check.number);
        if (value == facts.variables.end() || !value->second) {
            result.measured = "-"; // vacant
            result.expected = shownNumber(check.expect);
        } else {
            within(*value->second);
        }
        break;
    }
    case K::Output: {
        auto value = facts.outputs.find(check.number);
        const int level = value == facts.outputs.end() ? -1 : value->second;
        result.measured = std::to_string(level);
        result.expected = shownNumber(check.expect);
        result.passed = level == static_cast<int>(check.expect);
        result.target = {CheckTarget::Kind::Output, check.number, {}, 0};
        break;
    }
    case K::Responded: {
        result.expected = check.code + " → " + check.key + " ≤ " + shownNumber(check.within) + " s";
        const Event* alarm = nullptr;
        for (const Event& event : facts.events) {
            if (event.kind == Event::Kind::Alarm && alarmKey(event.alarm.code) == check.code) {
                alarm = &event;
                break;
            }
        }
        if (!alarm) {
            result.measured = "-";
            break;
        }
        result.target = lineTarget(alarm->alarm);
        result.measured = check.code + " → -";
        for (const PressedKey& key : facts.keys) {
            if (key.name == check.key && key.t >= alarm->time - 1e-9) {
                const double after = key.t - alarm->time;
                result.measured = check.code + " → " + check.key + " " + shownNumber(after) + " s";
                result.passed = after <= check.within + 1e-9;
                break;
            }
        }
        break;
    }
    case K::FileLine: {
        const std::optional<std::string> line =
            fileLine((std::filesystem::path(facts.machineFolder) / check.file).string(), check.line);
        result.measured = line ? *line : "-";
        result.expected = trimmed(check.text);
        result.passed = line && codeOf(*line) == codeOf(check.text);
        result.target = {CheckTarget::Kind::Line, 0, check.file, check.line};
        break;
    }
    case K::Finished: {
        int runs = 0;
        for (const Event& event : facts.events) {
            runs += event.kind == Event::Kind::Finished && (check.file.empty() || event.program == check.file);
        }
        result.measured = std::to_string(runs);
        result.expected = "≥ " + shownNumber(check.expect);
        result.passed = runs >= static_cast<int>(check.expect);
        break;
    }
    case K::TimeUsed:
        result.measured = shownNumber(facts.timeUsed) + " s";
        result.expected = "≤ " + shownNumber(check.within) + " s";
        result.passed = facts.timeUsed <= check.within + 1e-9;
        break;
    }
    if (!result.passed) {
        result.reason = check.why;
    }
    return result;
}

} // namespace

Verdict gradeAttempt(const Exercise& exercise, const AttemptFacts& facts) {
    Verdict verdict;
    verdict.exercise = exercise.name;
    verdict.timeUsed = facts.timeUsed;
    verdict.timeLimit = exercise.timeLimit;
    verdict.timedOut = facts.timeUsed > exercise.timeLimit + 1e-9;
    int passed = 0;
    for (const Check& check : exercise.checks) {
        verdict.checks.push_back(evaluate(check, facts));
        passed += verdict.checks.back().passed;
    }
    verdict.passed = passed == static_cast<int>(verdict.checks.size()) && !verdict.timedOut;
    verdict.score = verdict.checks.empty() ? 0 : static_cast<int>(std::lround(100.0 * passed / static_cast<double>(verdict.checks.size())));
    return verdict;
}

std::string verdictJson(const Verdict& verdict) {
    using nlohmann::json;
    json checks = json::array();
    for (const CheckResult& check : verdict.checks) {
        json entry{{"id", check.id},
                   {"kind", std::string(checkKindName(check.kind))},
                   {"passed", check.passed},
                   {"measured", check.measured},
                   {"expected", check.expected}};
        if (!check.passed) {
            entry["reason"] = {{"zh_CN", check.reason.chinese}, {"en", check.reason.english}};
        }
        switch (check.target.kind) {
        case CheckTarget::Kind::None: break;
        case CheckTarget::Kind::Parameter: entry["points_to"] = {{"parameter", check.target.number}}; break;
        case CheckTarget::Kind::Output: entry["points_to"] = {{"output", check.target.number}}; break;
        case CheckTarget::Kind::Tool: entry["points_to"] = {{"tool", check.target.number}}; break;
        case CheckTarget::Kind::Line: entry["points_to"] = {{"file", check.target.file}, {"line", check.target.line}}; break;
        }
        checks.push_back(std::move(entry));
    }
    json out{{"exercise", verdict.exercise},
             {"trainee", verdict.trainee},
             {"passed", verdict.passed},
             {"score", verdict.score},
             {"time_used", std::round(verdict.timeUsed * 1000.0) / 1000.0},
             {"time_limit", verdict.timeLimit},
             {"timed_out", verdict.timedOut},
             {"hints_used", verdict.hintsUsed},
             {"checks", std::move(checks)}};
    return out.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

} // namespace m350::training
