#include "ui/training/ClassReport.h"

#include "core/config/MachineConfig.h"
#include "core/training/ExerciseFile.h"
#include "ui/training/AttemptFile.h"
#include "ui/training/AttemptGrader.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>

#include <algorithm>

#include <QCoreApplication>

namespace m350::ui {

namespace {

QString csvField(QString text) {
    if (text.contains(QLatin1Char(',')) || text.contains(QLatin1Char('"')) || text.contains(QLatin1Char('\n'))) {
        text.replace(QStringLiteral("\""), QStringLiteral("\"\""));
        return QLatin1Char('"') + text + QLatin1Char('"');
    }
    return text;
}

QString timeText(double seconds) {
    const int s = static_cast<int>(std::lround(seconds));
    return QStringLiteral("%1:%2").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'));
}

QString failedChecks(const training::Verdict& verdict) {
    QStringList ids;
    for (const training::CheckResult& check : verdict.checks) {
        if (!check.passed) {
            ids.append(QString::fromStdString(check.id));
        }
    }
    if (verdict.timedOut) {
        ids.append(QStringLiteral("time-out"));
    }
    return ids.join(QLatin1Char(' '));
}

bool better(const ClassAttempt& a, const ClassAttempt& b) {
    if (a.verdict->passed != b.verdict->passed) {
        return a.verdict->passed;
    }
    if (a.verdict->score != b.verdict->score) {
        return a.verdict->score > b.verdict->score;
    }
    return a.verdict->timeUsed < b.verdict->timeUsed;
}

QString escaped(const QString& text) { return text.toHtmlEscaped(); }

} // namespace

const ClassAttempt* ClassReport::best(const QString& trainee, const QString& exercise) const {
    const ClassAttempt* found = nullptr;
    for (const ClassAttempt& attempt : attempts) {
        if (attempt.trainee == trainee && attempt.exercise == exercise && attempt.verdict &&
            (!found || better(attempt, *found))) {
            found = &attempt;
        }
    }
    return found;
}

ClassReport gradeClass(const QString& attemptsFolder, const QString& exercisesFolder, const QByteArray& examKey,
                       bool requireChain, Language* language) {
    ClassReport report;
    const training::ExerciseListing listing =
        training::loadExercises(exercisesFolder.toStdString(), config::bundledMachinesDirectory());
    for (const training::Exercise& exercise : listing.exercises) {
        report.exercises.append(QString::fromStdString(exercise.name));
    }
    QStringList files;
    QDirIterator it(attemptsFolder, QStringList{QStringLiteral("*.jsonl")}, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        files.append(it.next());
    }
    files.sort();
    const QDir root(attemptsFolder);
    for (const QString& file : files) {
        ClassAttempt attempt;
        attempt.file = root.relativeFilePath(file);
        auto [exercise, trainee] = attemptHeader(file);
        const QFileInfo info(file);
        if (trainee.isEmpty()) {
            const QString folder = QFileInfo(info.absolutePath()).canonicalFilePath();
            trainee = folder != QFileInfo(attemptsFolder).canonicalFilePath()
                          ? info.dir().dirName()
                          : info.completeBaseName().section(QLatin1Char('-'), 0, 0);
        }
        if (exercise.isEmpty()) {
            for (const QString& name : report.exercises) {
                if (info.completeBaseName().contains(name) && name.size() > exercise.size()) {
                    exercise = name;
                }
            }
        }
        attempt.trainee = trainee;
        attempt.exercise = exercise;
        if (!report.exercises.contains(exercise)) {
            attempt.error = QCoreApplication::translate("m350::ui::ClassReport", "%1: no exercise \"%2\" in %3").arg(attempt.file, exercise, exercisesFolder);
        } else {
            GradeRequest request;
            request.exerciseFolder = QDir(exercisesFolder).filePath(exercise);
            request.attemptFile = file;
            request.examKey = examKey;
            request.requireChain = requireChain;
            request.language = language;
            GradeOutcome outcome = gradeAttemptFile(request);
            attempt.verdict = std::move(outcome.verdict);
            attempt.error = outcome.error;
        }
        if (!report.trainees.contains(trainee)) {
            report.trainees.append(trainee);
        }
        report.attempts.push_back(std::move(attempt));
    }
    report.trainees.sort();
    return report;
}

QByteArray classReportCsv(const ClassReport& report) {
    QString out = QStringLiteral("trainee,exercise,passed,score,time_s,hints,failed_checks,attempts,file\n");
    for (const QString& trainee : report.trainees) {
        for (const QString& exercise : report.exercises) {
            const ClassAttempt* best = report.best(trainee, exercise);
            if (!best) {
                continue;
            }
            const auto tries = std::count_if(report.attempts.begin(), report.attempts.end(), [&](const ClassAttempt& a) {
                return a.trainee == trainee && a.exercise == exercise;
            });
            const training::Verdict& v = *best->verdict;
            out += QStringList{csvField(trainee), csvField(exercise), v.passed ? QStringLiteral("yes") : QStringLiteral("no"),
                               QString::number(v.score), QString::number(v.timeUsed, 'f', 1), QString::number(v.hintsUsed),
                               csvField(failedChecks(v)), QString::number(tries), csvField(best->file)}
                       .join(QLatin1Char(',')) +
                   QLatin1Char('\n');
        }
    }
    for (const ClassAttempt& attempt : report.attempts) {
        if (!attempt.verdict) {
            out += QStringList{csvField(attempt.trainee), csvField(attempt.exercise), QStringLiteral("error"), QString(), QString(),
                               QString(), csvField(attempt.error), QStringLiteral("1"), csvField(attempt.file)}
                       .join(QLatin1Char(',')) +
                   QLatin1Char('\n');
        }
    }
    return out.toUtf8();
}

QByteArray classReportHtml(const ClassReport& report, const QString& title) {
    QString html;
    html += QStringLiteral(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"zh-CN\">\n"
        "<head><meta charset=\"UTF-8\"/><title>%1</title>\n<style>\n"
        "body{font-family:sans-serif;margin:1em;background:#fff;color:#222}\n"
        "table{border-collapse:collapse;margin-bottom:2em}th,td{border:1px solid #999;padding:4px 8px;text-align:left}\n"
        "th{background:#ddd;cursor:pointer}td.pass{background:#d8f5d0}td.fail{background:#f8d7d3}td.none{color:#999}\n"
        "</style>\n<script>\n//<![CDATA[\n"
        "function sortBy(table,col){var body=table.tBodies[0];var rows=Array.prototype.slice.call(body.rows);"
        "var dir=table.getAttribute('data-col')==String(col)&&table.getAttribute('data-dir')=='up'?-1:1;"
        "rows.sort(function(a,b){var x=a.cells[col].getAttribute('data-sort')||a.cells[col].textContent;"
        "var y=b.cells[col].getAttribute('data-sort')||b.cells[col].textContent;var nx=parseFloat(x),ny=parseFloat(y);"
        "if(!isNaN(nx)&&!isNaN(ny))return (nx-ny)*dir;return x.localeCompare(y)*dir;});"
        "rows.forEach(function(r){body.appendChild(r);});table.setAttribute('data-col',col);"
        "table.setAttribute('data-dir',dir==1?'up':'down');}\n"
        "//]]>\n</script>\n</head>\n<body>\n<h1>%1</h1>\n")
                .arg(escaped(title));
    html += QStringLiteral("<table id=\"class\"><thead><tr><th onclick=\"sortBy(this.closest('table'),0)\">学员 Trainee</th>");
    for (int c = 0; c < report.exercises.size(); ++c) {
        html += QStringLiteral("<th onclick=\"sortBy(this.closest('table'),%1)\">%2</th>").arg(c + 1).arg(escaped(report.exercises[c]));
    }
    html += QStringLiteral("<th onclick=\"sortBy(this.closest('table'),%1)\">通过 Passed</th></tr></thead>\n<tbody>\n")
                .arg(report.exercises.size() + 1);
    for (const QString& trainee : report.trainees) {
        html += QStringLiteral("<tr><td>%1</td>").arg(escaped(trainee));
        int passed = 0;
        for (const QString& exercise : report.exercises) {
            const ClassAttempt* best = report.best(trainee, exercise);
            if (!best) {
                html += QStringLiteral("<td class=\"none\" data-sort=\"-1\">-</td>");
                continue;
            }
            const training::Verdict& v = *best->verdict;
            passed += v.passed;
            const QString failing = failedChecks(v);
            html += QStringLiteral("<td class=\"%1\" data-sort=\"%2\">%3 %4 (%5)%6</td>")
                        .arg(v.passed ? QStringLiteral("pass") : QStringLiteral("fail"))
                        .arg(v.score)
                        .arg(v.passed ? QStringLiteral("✓") : QStringLiteral("✗"))
                        .arg(v.score)
                        .arg(timeText(v.timeUsed))
                        .arg(failing.isEmpty() ? QString() : QStringLiteral("<br/>") + escaped(failing));
        }
        html += QStringLiteral("<td data-sort=\"%1\">%1</td></tr>\n").arg(passed);
    }
    html += QStringLiteral("</tbody></table>\n<h2>每次练习 Attempts</h2>\n<table id=\"attempts\"><thead><tr>"
                           "<th onclick=\"sortBy(this.closest('table'),0)\">学员 Trainee</th>"
                           "<th onclick=\"sortBy(this.closest('table'),1)\">练习 Exercise</th>"
                           "<th onclick=\"sortBy(this.closest('table'),2)\">得分 Score</th>"
                           "<th onclick=\"sortBy(this.closest('table'),3)\">用时 Time</th>"
                           "<th onclick=\"sortBy(this.closest('table'),4)\">未通过的检查 Failed checks</th>"
                           "<th onclick=\"sortBy(this.closest('table'),5)\">文件 File</th></tr></thead>\n<tbody>\n");
    for (const ClassAttempt& attempt : report.attempts) {
        if (attempt.verdict) {
            const training::Verdict& v = *attempt.verdict;
            QString reasons;
            for (const training::CheckResult& check : v.checks) {
                if (!check.passed) {
                    reasons += QStringLiteral("<br/>%1: %2 / %3").arg(escaped(QString::fromStdString(check.id)),
                                                                    escaped(QString::fromStdString(check.reason.chinese)),
                                                                    escaped(QString::fromStdString(check.reason.english)));
                }
            }
            html += QStringLiteral("<tr><td>%1</td><td>%2</td><td class=\"%3\" data-sort=\"%4\">%4</td><td data-sort=\"%5\">%6</td>"
                                   "<td>%7%8</td><td>%9</td></tr>\n")
                        .arg(escaped(attempt.trainee), escaped(attempt.exercise), v.passed ? QStringLiteral("pass") : QStringLiteral("fail"))
                        .arg(v.score)
                        .arg(v.timeUsed, 0, 'f', 1)
                        .arg(timeText(v.timeUsed), escaped(failedChecks(v)), reasons, escaped(attempt.file));
        } else {
            html += QStringLiteral("<tr><td>%1</td><td>%2</td><td class=\"fail\" data-sort=\"-1\">-</td><td>-</td><td>%3</td><td>%4</td></tr>\n")
                        .arg(escaped(attempt.trainee), escaped(attempt.exercise), escaped(attempt.error), escaped(attempt.file));
        }
    }
    html += QStringLiteral("</tbody></table>\n</body>\n</html>\n");
    return html.toUtf8();
}

} // namespace m350::ui
