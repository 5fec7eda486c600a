#include "core/training/CheckToml.h"

#include "core/common/Alarm.h"

#include <algorithm>
#include <cmath>

namespace m350::training {

namespace fs = std::filesystem;

namespace {

const std::vector<std::pair<std::string_view, Check::Kind>>& checkKinds() {
    static const std::vector<std::pair<std::string_view, Check::Kind>> kinds{
        {"spindle_tool", Check::Kind::SpindleTool}, {"pocket_tool", Check::Kind::PocketTool},
        {"no_alarm", Check::Kind::NoAlarm},         {"alarm", Check::Kind::Alarm},
        {"no_crash", Check::Kind::NoCrash},         {"parameter", Check::Kind::Parameter},
        {"tool_offset", Check::Kind::ToolOffset},   {"variable", Check::Kind::Variable},
        {"output", Check::Kind::Output},            {"responded", Check::Kind::Responded},
        {"file_line", Check::Kind::FileLine},       {"finished", Check::Kind::Finished},
        {"time_used", Check::Kind::TimeUsed},
    };
    return kinds;
}

// The alarm codes a check may name (alarmKey's words).
bool knownAlarmCode(std::string_view code) {
    for (int c = 0; c <= static_cast<int>(AlarmCode::RightsLimited); ++c) {
        if (alarmKey(static_cast<AlarmCode>(c)) == code) {
            return true;
        }
    }
    return false;
}

} // namespace

Check readCheck(const ExerciseTomlReader& in, const toml::table& t, const toml::source_region& where,
                const fs::path& machineFolder) {
    Check check;
    check.place = {in.file(), static_cast<int>(where.begin.line), static_cast<int>(where.begin.column)};
    check.id = in.text(in.required(t, "id", where), "id");
    const toml::node& kindNode = in.required(t, "kind", where);
    const std::string kind = in.text(kindNode, "kind");
    const auto& kinds = checkKinds();
    auto found = std::find_if(kinds.begin(), kinds.end(), [&](const auto& k) { return k.first == kind; });
    if (found == kinds.end()) {
        std::string list;
        for (const auto& k : kinds) {
            list += (list.empty() ? "" : ", ") + std::string(k.first);
        }
        in.refuse(kindNode.source(), message("exercise_unknown_check", {kind, list}));
    }
    check.kind = found->second;
    check.why = in.localText(in.required(t, "why", where), "why");
    using K = Check::Kind;
    auto numberOf = [&](std::string_view key, int low, int high) { check.number = in.whole(in.required(t, key, where), key, low, high); };
    auto expectNumber = [&] {
        check.expect = in.number(in.required(t, "expect", where), "expect");
        if (const toml::node* tolerance = t.get("tolerance")) {
            check.tolerance = std::abs(in.number(*tolerance, "tolerance"));
        }
    };
    auto alarmCode = [&](bool requiredCode) {
        const toml::node* code = t.get("code");
        if (!code && !requiredCode) {
            return;
        }
        const toml::node& node = code ? *code : in.required(t, "code", where);
        check.code = in.text(node, "code");
        if (!knownAlarmCode(check.code)) {
            in.refuse(node.source(), message("exercise_unknown_alarm_code", {check.code}));
        }
    };
    switch (check.kind) {
    case K::SpindleTool:
        in.onlyKeys(t, {"id", "kind", "why", "expect"}, "checks");
        check.expect = in.whole(in.required(t, "expect", where), "expect", 0, 9999);
        break;
    case K::PocketTool:
        in.onlyKeys(t, {"id", "kind", "why", "pocket", "expect"}, "checks");
        check.number = in.whole(in.required(t, "pocket", where), "pocket", 1, 999);
        check.expect = in.whole(in.required(t, "expect", where), "expect", 0, 9999);
        break;
    case K::NoAlarm:
    case K::NoCrash:
        in.onlyKeys(t, {"id", "kind", "why"}, "checks");
        break;
    case K::Alarm:
        in.onlyKeys(t, {"id", "kind", "why", "code"}, "checks");
        alarmCode(true);
        break;
    case K::Parameter:
        in.onlyKeys(t, {"id", "kind", "why", "number", "expect", "tolerance"}, "checks");
        numberOf("number", 0, 99999);
        expectNumber();
        break;
    case K::ToolOffset:
        in.onlyKeys(t, {"id", "kind", "why", "tool", "expect", "tolerance"}, "checks");
        numberOf("tool", 1, 9999);
        expectNumber();
        break;
    case K::Variable:
        in.onlyKeys(t, {"id", "kind", "why", "number", "expect", "tolerance"}, "checks");
        numberOf("number", 1, 99999);
        expectNumber();
        break;
    case K::Output:
        in.onlyKeys(t, {"id", "kind", "why", "number", "expect"}, "checks");
        numberOf("number", 1, 99);
        check.expect = in.whole(in.required(t, "expect", where), "expect", 0, 1);
        break;
    case K::Responded:
        in.onlyKeys(t, {"id", "kind", "why", "key", "within", "code"}, "checks");
        check.key = in.text(in.required(t, "key", where), "key");
        check.within = in.number(in.required(t, "within", where), "within");
        alarmCode(true);
        break;
    case K::FileLine: {
        in.onlyKeys(t, {"id", "kind", "why", "file", "line", "text"}, "checks");
        const toml::node& fileNode = in.required(t, "file", where);
        check.file = in.text(fileNode, "file");
        if (fs::path(check.file).is_absolute() || check.file.find("..") != std::string::npos ||
            !fs::is_regular_file(machineFolder / check.file)) {
            in.refuse(fileNode.source(), message("exercise_no_machine_file", {check.file, machineFolder.string()}));
        }
        check.line = in.whole(in.required(t, "line", where), "line", 1, 1000000);
        check.text = in.text(in.required(t, "text", where), "text");
        break;
    }
    case K::Finished:
        in.onlyKeys(t, {"id", "kind", "why", "program", "expect"}, "checks");
        if (const toml::node* program = t.get("program")) {
            check.file = in.text(*program, "program");
        }
        check.expect = 1;
        if (const toml::node* times = t.get("expect")) {
            check.expect = in.whole(*times, "expect", 1, 1000000);
        }
        break;
    case K::TimeUsed:
        in.onlyKeys(t, {"id", "kind", "why", "within"}, "checks");
        check.within = in.number(in.required(t, "within", where), "within");
        break;
    }
    return check;
}


std::string_view checkKindName(Check::Kind kind) {
    for (const auto& [name, k] : checkKinds()) {
        if (k == kind) {
            return name;
        }
    }
    return "unknown";
}

} // namespace m350::training
