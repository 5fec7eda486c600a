#include "core/training/ExerciseFile.h"

#include "core/common/Alarm.h"
#include "core/common/ResourceDirectory.h"
#include "core/files/MachineFileRead.h"
#include "core/files/Toml.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <set>

namespace m350::training {

namespace fs = std::filesystem;

std::string ExerciseError::where() const {
    std::string text = place.file;
    if (place.line > 0) {
        text += ":" + std::to_string(place.line);
        if (place.column > 0) {
            text += ":" + std::to_string(place.column);
        }
    }
    return text;
}

namespace {

struct ExerciseRefusal {
    ExerciseError error;
};

// Reads exercise.toml's tables; every refusal throws ExerciseRefusal at the node concerned.
class ExerciseTomlReader {
public:
    explicit ExerciseTomlReader(std::string file) : file_(std::move(file)) {}

    [[noreturn]] void refuse(const toml::source_region& where, Message words) const {
        ExerciseRefusal refusal;
        refusal.error.place.file = file_;
        refusal.error.place.line = static_cast<int>(where.begin.line);
        refusal.error.place.column = static_cast<int>(where.begin.column);
        refusal.error.words = std::move(words);
        throw refusal;
    }
    [[noreturn]] void refuseFile(Message words) const { refuse(toml::source_region{}, std::move(words)); }

    // Every key of `table` is one of `known` (a typo in an exercise is a check that never runs).
    void onlyKeys(const toml::table& table, std::initializer_list<std::string_view> known, const std::string& in) const {
        for (auto&& [key, value] : table) {
            if (std::find(known.begin(), known.end(), key.str()) == known.end()) {
                std::string list;
                for (std::string_view name : known) {
                    list += (list.empty() ? "" : ", ") + std::string(name);
                }
                refuse(key.source(), message("exercise_unknown_key", {std::string(key.str()), in, list}));
            }
        }
    }

    const toml::node& required(const toml::table& table, std::string_view key, const toml::source_region& where) const {
        const toml::node* node = table.get(key);
        if (!node) {
            refuse(where, message("exercise_missing_key", {std::string(key)}));
        }
        return *node;
    }

    double number(const toml::node& node, std::string_view key) const {
        std::optional<double> value = node.value<double>();
        if (!value || !std::isfinite(*value)) {
            refuse(node.source(), message("exercise_not_a_number", {std::string(key)}));
        }
        return *value;
    }

    int whole(const toml::node& node, std::string_view key, int low, int high) const {
        std::optional<std::int64_t> value = node.value_exact<std::int64_t>();
        if (!value || *value < low || *value > high) {
            refuse(node.source(), message("exercise_not_whole", {std::string(key), std::to_string(low), std::to_string(high)}));
        }
        return static_cast<int>(*value);
    }

    std::string text(const toml::node& node, std::string_view key) const {
        std::optional<std::string> value = node.value_exact<std::string>();
        if (!value) {
            refuse(node.source(), message("exercise_not_text", {std::string(key)}));
        }
        return *value;
    }

    const toml::table& table(const toml::node& node, std::string_view key) const {
        const toml::table* t = node.as_table();
        if (!t) {
            refuse(node.source(), message("exercise_not_table", {std::string(key)}));
        }
        return *t;
    }

    // [title] zh_CN = "..." en = "...": both, never one alone (every word a trainee sees is in both).
    LocalText localText(const toml::node& node, std::string_view key) const {
        const toml::table& t = table(node, key);
        onlyKeys(t, {"zh_CN", "en"}, std::string(key));
        return {text(required(t, "zh_CN", node.source()), std::string(key) + ".zh_CN"),
                text(required(t, "en", node.source()), std::string(key) + ".en")};
    }

    std::vector<LocalText> hints(const toml::node& node) const {
        const toml::table& t = table(node, "hints");
        onlyKeys(t, {"zh_CN", "en"}, "hints");
        const toml::array* zh = required(t, "zh_CN", node.source()).as_array();
        const toml::array* en = required(t, "en", node.source()).as_array();
        if (!zh || !en || zh->size() != en->size()) {
            refuse(node.source(), message("exercise_hints_pair"));
        }
        std::vector<LocalText> out;
        for (std::size_t i = 0; i < zh->size(); ++i) {
            out.push_back({text(*zh->get(i), "hints.zh_CN"), text(*en->get(i), "hints.en")});
        }
        return out;
    }

    const std::string& file() const { return file_; }

private:
    std::string file_;
};

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

InjectedFault readFault(const ExerciseTomlReader& in, const toml::table& t, const toml::source_region& where) {
    in.onlyKeys(t, {"at", "after", "input", "fault", "level", "seconds"}, "faults");
    InjectedFault fault;
    fault.at = in.number(in.required(t, "at", where), "at");
    if (const toml::node* after = t.get("after")) {
        const std::string event = in.text(*after, "after");
        if (event == "start") {
            fault.after = InjectedFault::After::FirstStart;
        } else if (event == "mdi") {
            fault.after = InjectedFault::After::FirstMdiRun;
        } else if (event != "begin") {
            in.refuse(after->source(), message("exercise_unknown_fault_event", {event}));
        }
    }
    fault.input = in.whole(in.required(t, "input", where), "input", 1, 999);
    const toml::node& kind = in.required(t, "fault", where);
    fault.fault = in.text(kind, "fault");
    static const std::set<std::string> faults{"stuck", "slow", "bouncing", "pressed", "none"};
    if (!faults.count(fault.fault)) {
        in.refuse(kind.source(), message("exercise_unknown_fault", {fault.fault}));
    }
    if (const toml::node* level = t.get("level")) {
        fault.level = in.whole(*level, "level", 0, 1);
    }
    if (const toml::node* seconds = t.get("seconds")) {
        fault.seconds = in.number(*seconds, "seconds");
    }
    return fault;
}

// Each entry of an array of tables, with where it stands.
template <typename Each>
void forEachTable(const ExerciseTomlReader& in, const toml::node& node, std::string_view key, Each each) {
    const toml::array* entries = node.as_array();
    if (!entries || !entries->is_array_of_tables()) {
        in.refuse(node.source(), message("exercise_not_table_array", {std::string(key)}));
    }
    for (const toml::node& entry : *entries) {
        each(*entry.as_table(), entry.source());
    }
}

Exercise readExercise(const fs::path& folder, const fs::path& machinesFolder) {
    const fs::path file = folder / kExerciseFileName;
    ExerciseTomlReader in(file.string());
    std::string text;
    if (auto why = files::readMachineFile(file, text)) {
        in.refuseFile(message("exercise_unreadable", {bilingual(*why)}));
    }
    toml::table root;
    try {
        root = files::parseTomlText(text, file.string());
    } catch (const toml::parse_error& e) {
        in.refuse(e.source(), message("exercise_bad_toml", {std::string(e.description())}));
    }
    in.onlyKeys(root, {"level", "time_limit", "machine", "title", "task", "hints", "start", "parameters", "lines", "files",
                       "breaks", "faults", "checks"},
                "exercise.toml");
    const toml::source_region top{{1, 1}, {1, 1}, nullptr};
    Exercise exercise;
    exercise.folder = folder.string();
    exercise.name = folder.filename().string();
    exercise.level = in.whole(in.required(root, "level", top), "level", 1, 3);
    exercise.timeLimit = in.number(in.required(root, "time_limit", top), "time_limit");
    if (exercise.timeLimit <= 0.0) {
        in.refuse(root.get("time_limit")->source(), message("exercise_time_limit"));
    }
    const toml::node& machineNode = in.required(root, "machine", top);
    exercise.machine = in.text(machineNode, "machine");
    const fs::path machine = machinesFolder / exercise.machine;
    if (exercise.machine.empty() || exercise.machine.find('/') != std::string::npos || exercise.machine.find("..") != std::string::npos ||
        !fs::is_regular_file(machine / "machine.toml")) {
        in.refuse(machineNode.source(), message("exercise_no_machine", {exercise.machine, machinesFolder.string()}));
    }
    exercise.title = in.localText(in.required(root, "title", top), "title");
    exercise.task = in.localText(in.required(root, "task", top), "task");
    if (const toml::node* hints = root.get("hints")) {
        exercise.hints = in.hints(*hints);
    }
    if (const toml::node* start = root.get("start")) {
        const toml::table& t = in.table(*start, "start");
        in.onlyKeys(t, {"tool", "homed"}, "start");
        if (const toml::node* tool = t.get("tool")) {
            exercise.startTool = in.whole(*tool, "start.tool", 0, 9999);
        }
        if (const toml::node* homed = t.get("homed")) {
            std::optional<bool> value = homed->value_exact<bool>();
            if (!value) {
                in.refuse(homed->source(), message("exercise_not_bool", {"start.homed"}));
            }
            exercise.homed = *value;
        }
    }
    if (const toml::node* parameters = root.get("parameters")) {
        for (auto&& [key, value] : in.table(*parameters, "parameters")) {
            int number = -1;
            const std::string name(key.str());
            if (name.empty() || name.size() > 5 || !std::all_of(name.begin(), name.end(), [](char c) { return c >= '0' && c <= '9'; })) {
                in.refuse(key.source(), message("exercise_parameter_number", {name}));
            }
            number = std::stoi(name);
            exercise.parameters[number] = in.number(value, "parameters." + name);
        }
    }
    if (const toml::node* lines = root.get("lines")) {
        forEachTable(in, *lines, "lines", [&](const toml::table& t, const toml::source_region& where) {
            in.onlyKeys(t, {"file", "line", "text"}, "lines");
            LineChange change;
            const toml::node& fileNode = in.required(t, "file", where);
            change.file = in.text(fileNode, "file");
            if (fs::path(change.file).is_absolute() || change.file.find("..") != std::string::npos ||
                !fs::is_regular_file(machine / change.file)) {
                in.refuse(fileNode.source(), message("exercise_no_machine_file", {change.file, machine.string()}));
            }
            change.line = in.whole(in.required(t, "line", where), "line", 1, 1000000);
            change.text = in.text(in.required(t, "text", where), "text");
            exercise.lines.push_back(std::move(change));
        });
    }
    if (const toml::node* copied = root.get("files")) {
        const toml::array* names = copied->as_array();
        if (!names) {
            in.refuse(copied->source(), message("exercise_not_text", {"files"}));
        }
        for (const toml::node& name : *names) {
            std::string copiedName = in.text(name, "files");
            if (copiedName.find('/') != std::string::npos || copiedName.find("..") != std::string::npos ||
                !fs::is_regular_file(folder / copiedName)) {
                in.refuse(name.source(), message("exercise_no_file", {copiedName, folder.string()}));
            }
            exercise.files.push_back(std::move(copiedName));
        }
    }
    if (const toml::node* breaks = root.get("breaks")) {
        forEachTable(in, *breaks, "breaks", [&](const toml::table& t, const toml::source_region& where) {
            in.onlyKeys(t, {"tool", "short_by", "at"}, "breaks");
            exercise.breaks.push_back({in.whole(in.required(t, "tool", where), "tool", 1, 9999),
                                       in.number(in.required(t, "short_by", where), "short_by"),
                                       in.number(in.required(t, "at", where), "at")});
        });
    }
    if (const toml::node* faults = root.get("faults")) {
        forEachTable(in, *faults, "faults", [&](const toml::table& t, const toml::source_region& where) {
            exercise.faults.push_back(readFault(in, t, where));
        });
    }
    // the checks see the machine folder as the exercise leaves it: a file_line check names one of its files
    forEachTable(in, in.required(root, "checks", top), "checks", [&](const toml::table& t, const toml::source_region& where) {
        Check check = readCheck(in, t, where, machine);
        for (const Check& earlier : exercise.checks) {
            if (earlier.id == check.id) {
                in.refuse(where, message("exercise_check_twice", {check.id, std::to_string(earlier.place.line)}));
            }
        }
        exercise.checks.push_back(std::move(check));
    });
    if (exercise.checks.empty()) {
        in.refuse(root.get("checks")->source(), message("exercise_no_checks"));
    }
    return exercise;
}

} // namespace

std::string_view checkKindName(Check::Kind kind) {
    for (const auto& [name, k] : checkKinds()) {
        if (k == kind) {
            return name;
        }
    }
    return "unknown";
}

std::variant<Exercise, ExerciseError> loadExercise(const std::string& folder, const std::string& machinesFolder) {
    try {
        return readExercise(fs::path(folder), fs::path(machinesFolder));
    } catch (const ExerciseRefusal& refusal) {
        return refusal.error;
    } catch (const fs::filesystem_error& e) {
        ExerciseError unreadable;
        unreadable.place.file = folder;
        unreadable.words = message("exercise_unreadable", {e.code().message()});
        return unreadable;
    }
}

ExerciseListing loadExercises(const std::string& folder, const std::string& machinesFolder) {
    ExerciseListing listing;
    std::vector<fs::path> folders;
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
        if (entry.is_directory(error) && fs::exists(entry.path() / kExerciseFileName, error)) {
            folders.push_back(entry.path());
        }
    }
    if (error) {
        ExerciseError unreadable;
        unreadable.place.file = folder;
        unreadable.words = message("exercise_unreadable", {error.message()});
        listing.errors.push_back(std::move(unreadable));
    }
    std::sort(folders.begin(), folders.end());
    for (const fs::path& path : folders) {
        auto loaded = loadExercise(path.string(), machinesFolder);
        if (auto* exercise = std::get_if<Exercise>(&loaded)) {
            listing.exercises.push_back(std::move(*exercise));
        } else {
            listing.errors.push_back(std::get<ExerciseError>(loaded));
        }
    }
    return listing;
}

std::string bundledExercisesDirectory() { return resourceDirectory() + "/exercises"; }

} // namespace m350::training
