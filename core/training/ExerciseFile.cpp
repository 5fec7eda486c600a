#include "core/training/ExerciseFile.h"

#include "core/training/CheckToml.h"
#include "core/training/ExerciseTomlReader.h"

#include "core/common/ResourceDirectory.h"

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
    const toml::table root = in.parse();
    in.onlyKeys(root, {"level", "time_limit", "machine", "title", "task", "hints", "start", "parameters", "lines", "files", "programs",
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
    auto readCopied = [&](const char* key, std::vector<std::string>& into) {
        const toml::node* copied = root.get(key);
        if (!copied) {
            return;
        }
        const toml::array* names = copied->as_array();
        if (!names) {
            in.refuse(copied->source(), message("exercise_not_text", {key}));
        }
        for (const toml::node& name : *names) {
            std::string copiedName = in.text(name, key);
            if (copiedName.find('/') != std::string::npos || copiedName.find("..") != std::string::npos ||
                !fs::is_regular_file(folder / copiedName)) {
                in.refuse(name.source(), message("exercise_no_file", {copiedName, folder.string()}));
            }
            into.push_back(std::move(copiedName));
        }
    };
    readCopied("files", exercise.files);
    readCopied("programs", exercise.programs);
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
