#pragma once

#include "core/common/Message.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace m350::training {

// Words an exercise's author wrote in both languages (title, task, hints, a check's explanation).
struct LocalText {
    std::string chinese;
    std::string english;
    const std::string& in(MessageLanguage language) const {
        return language == MessageLanguage::Chinese ? chinese : english;
    }
};

// A place in an exercise's files, for the messages that point at it.
struct ExercisePlace {
    std::string file;
    int line = 0;
    int column = 0;
};

// A line of a machine-folder file the exercise changes (a broken macro line to find).
struct LineChange {
    std::string file; // relative to the machine folder
    int line = 0;     // 1-based
    std::string text;
};

// A fault injected into an input while the attempt runs, as a trainer's `force` action.
struct InjectedFault {
    double at = 0.0;           // virtual s, counted from `after`
    // the attempt's start, the first START key, or the first MDI line run (F1-F6 on the MDI page)
    enum class After { Begin, FirstStart, FirstMdiRun } after = After::Begin;
    int input = 0;
    std::string fault = "stuck"; // stuck slow bouncing pressed none (the replay's force action)
    int level = 0;
    double seconds = 0.0;
};

// A tool of the simulated world that breaks (m350-sim --break): shorter by `shortBy` from `at` on.
struct ToolBreakage {
    int tool = 0;
    double shortBy = 0.0;
    double at = 0.0;
};

// One check of an attempt. `kind` says which fields count (ExerciseFile.cpp lists them).
struct Check {
    enum class Kind {
        SpindleTool, // tool in the spindle == expect
        PocketTool,  // tool in pocket `number` == expect
        NoAlarm,     // no alarm at all (RESET and E-stop by the operator included only when `code` names them)
        Alarm,       // an alarm of `code` (alarmKey) happened
        NoCrash,     // no crash alarm
        Parameter,   // parameter `number` within `tolerance` of expect
        ToolOffset,  // tool `number`'s Z offset (params 930+ on the M350, the tool table elsewhere)
        Variable,    // #number within tolerance of expect
        Output,      // OUT`number` == expect (0/1)
        Responded,   // the key `key` pressed within `within` s after the first alarm of `code`
        FileLine,    // line `line` of `file` (in the machine folder) reads `text` (trimmed)
        Finished,    // a run of `program` (empty: any) reached its end at least `expect` times
        TimeUsed,    // the attempt took at most `within` s
    };
    std::string id;
    Kind kind = Kind::NoAlarm;
    int number = 0;
    double expect = 0.0;
    double tolerance = 0.001;
    std::string code;     // an alarm code (crash, sensor_timeout ...)
    std::string key;      // a panel key (RESET ...)
    double within = 0.0;  // s
    std::string file;     // FileLine; Finished: the program
    int line = 0;
    std::string text;
    LocalText why; // said when the check fails
    ExercisePlace place; // the check in exercise.toml
};

std::string_view checkKindName(Check::Kind kind);

// An exercise folder (resources/exercises/NAME): exercise.toml read and checked.
struct Exercise {
    std::string name;   // the folder's name
    std::string folder; // its path
    int level = 1;      // 1-3
    double timeLimit = 0.0; // s of the attempt
    std::string machine;    // a bundled machine folder's name
    LocalText title;
    LocalText task;
    std::vector<LocalText> hints;
    // the start: the tool in the spindle (nullopt: as the folder says), the axes homed or not
    std::optional<int> startTool;
    bool homed = true;
    std::map<int, double> parameters; // written into params.toml
    std::vector<LineChange> lines;
    std::vector<std::string> files; // of the exercise folder, copied into the machine folder
    std::vector<std::string> programs; // of the exercise folder, copied into its programs/ (本地程序)
    std::vector<ToolBreakage> breaks;
    std::vector<InjectedFault> faults;
    std::vector<Check> checks;
};

// Why an exercise folder cannot be used: where, and what (by message id).
struct ExerciseError {
    ExercisePlace place;
    Message words;
    std::string where() const; // "file:line:col", "file:line" or "file"
};

} // namespace m350::training
