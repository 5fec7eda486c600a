#pragma once

#include "core/training/Verdict.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <vector>

namespace m350::ui {

class Language;

// A class's attempts graded together (m350-hmi --class-report FOLDER): every *.jsonl under the
// folder, the trainee named by the attempt's first line, else by its folder (a folder a trainee),
// else by its file name up to the first '-' or '.'; the exercise by its first line, else by the
// exercise whose name begins the file name. Each graded as the headless grader does.
struct ClassAttempt {
    QString file;
    QString trainee;
    QString exercise;
    std::optional<training::Verdict> verdict;
    QString error; // why it could not be graded
};

struct ClassReport {
    QStringList trainees;  // sorted
    QStringList exercises; // every exercise of the folder, in order
    std::vector<ClassAttempt> attempts;
    // The trainee's best attempt at the exercise (passed first, then the score, then the time),
    // nullptr when none was graded.
    const ClassAttempt* best(const QString& trainee, const QString& exercise) const;
};

ClassReport gradeClass(const QString& attemptsFolder, const QString& exercisesFolder, const QByteArray& examKey,
                       bool requireChain, Language* language);

// trainee,exercise,passed,score,time_s,hints,failed_checks,attempts,file: one row per trainee and
// exercise tried (the best attempt), then a row per attempt that could not be graded.
QByteArray classReportCsv(const ClassReport& report);
// One self-contained page (XHTML: its own style and script, nothing fetched): trainees x exercises
// with the score, the time and the failing checks, each column sortable by a click; then every
// attempt with its verdict.
QByteArray classReportHtml(const ClassReport& report, const QString& title);

} // namespace m350::ui
