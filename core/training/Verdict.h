#pragma once

#include "core/training/AttemptFacts.h"
#include "core/training/Exercise.h"

#include <string>
#include <vector>

namespace m350::training {

// Where a failed check sends the trainee: the parameter, the input or output, the tool, or the
// macro line concerned (an alarm's line, a changed file's line).
struct CheckTarget {
    enum class Kind { None, Parameter, Output, Tool, Line };
    Kind kind = Kind::None;
    int number = 0;
    std::string file; // Line: as the machine folder names it
    int line = 0;
};

struct CheckResult {
    std::string id;
    Check::Kind kind = Check::Kind::NoAlarm;
    bool passed = false;
    std::string measured; // language-neutral: numbers, codes, file:line
    std::string expected;
    LocalText reason; // the check's explanation when it failed; empty when it passed
    CheckTarget target;
};

struct Verdict {
    std::string exercise;
    std::string trainee;
    bool passed = false;     // every check passed
    int score = 0;           // 0-100: the share of checks passed
    double timeUsed = 0.0;   // s
    double timeLimit = 0.0;
    bool timedOut = false;
    int hintsUsed = 0;
    std::vector<CheckResult> checks;
};

// Grades the facts of an attempt against the exercise's checks.
Verdict gradeAttempt(const Exercise& exercise, const AttemptFacts& facts);

// The verdict as `--verdict OUT.json` writes it: each check with passed, measured, expected and,
// when failed, its reason in both languages and what it points at.
std::string verdictJson(const Verdict& verdict);

} // namespace m350::training
