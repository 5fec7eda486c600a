#pragma once

#include "core/training/Exercise.h"
#include "core/training/Verdict.h"
#include "ui/training/AttemptFile.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace m350::ui {

class Language;
class MachineSession;

// Grades a recorded attempt without anyone at the panel: the exercise's machine made afresh, the
// panel built offscreen on it (the pages, the dispatcher and the session a trainee's keys went
// through), the attempt played in virtual time with the exercise's faults, then the checks read
// the machine's end. The same verdict as the panel's hand-in, which reads the same facts.
struct GradeRequest {
    QString exerciseFolder;
    QString attemptFile;
    QByteArray examKey;         // the exam's key: the chain is checked with it
    bool requireChain = false;  // an exam: an attempt without an intact chain is refused
    Language* language = nullptr;
};

struct GradeOutcome {
    std::optional<training::Verdict> verdict;
    QString error; // why it could not be graded (exit 2): file:line:col and what
};

GradeOutcome gradeAttemptFile(const GradeRequest& request);

// The request's exercise and attempt, read and checked as the grader reads them (the chain, an
// exam's, the attempt being at that exercise); nullopt with `error` (file:line:col and what) when not.
struct AttemptAtExercise {
    training::Exercise exercise;
    Attempt attempt;
};
std::optional<AttemptAtExercise> readAttemptAtExercise(const GradeRequest& request, QString* error);

// The verdict on the machine as it stands once `attempt` has played to its hand-in: the facts the
// exercise's checks read (the display's events from `startDisplay`, the time the attempt began),
// the attempt's keys, time used, hints and hand-in. `folder`: the attempt's machine folder.
training::Verdict gradePlayedAttempt(MachineSession& session, const training::Exercise& exercise, const Attempt& attempt,
                                     double startDisplay, const QString& folder);

// The verdict is never written onto the attempt it grades nor into the exercise folder: why not,
// else nullopt.
std::optional<QString> refusedVerdictOutput(const QString& verdict, const QString& attempt, const QString& exerciseFolder);

} // namespace m350::ui
