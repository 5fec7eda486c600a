#include "app/hmi/GradeCommand.h"

#include "app/hmi/ExamOption.h"

#include "app/hmi/HmiOutputs.h"
#include "app/hmi/Refusal.h"
#include "ui/i18n/Language.h"
#include "core/training/Exam.h"
#include "core/training/ExerciseFile.h"
#include "ui/training/AttemptGrader.h"
#include "ui/training/ClassReport.h"

#include <variant>

#include <cstdio>

namespace m350::hmi {



int classReportCommand(const HmiOptions& o, ui::Language& language) {
    std::string key;
    if (!o.exam.empty()) {
        training::Exam exam;
        if (auto refused = readExamOption(o.exam, language, &exam)) {
            return refuse(QString::fromStdString(*refused));
        }
        key = exam.key;
    }
    const QString exercises = QString::fromStdString(o.exercises.empty() ? training::bundledExercisesDirectory() : o.exercises);
    const ui::ClassReport report = ui::gradeClass(QString::fromStdString(o.classReport), exercises, QByteArray::fromStdString(key),
                                                  !o.exam.empty(), &language);
    const QByteArray csv = ui::classReportCsv(report);
    std::fwrite(csv.constData(), 1, static_cast<std::size_t>(csv.size()), stdout);
    if (!o.reportCsv.empty()) {
        if (auto error = writeOutput(o.reportCsv, csv)) {
            return refuse(QStringLiteral("--report-csv: %1").arg(*error));
        }
    }
    if (!o.reportHtml.empty()) {
        const QString title = QStringLiteral("M350 Studio 训练 Training: %1").arg(QString::fromStdString(o.classReport));
        if (auto error = writeOutput(o.reportHtml, ui::classReportHtml(report, title))) {
            return refuse(QStringLiteral("--report-html: %1").arg(*error));
        }
    }
    int failures = 0;
    for (const ui::ClassAttempt& attempt : report.attempts) {
        if (!attempt.verdict) {
            refuse(attempt.error);
            ++failures;
        }
    }
    return failures == 0 ? 0 : 2;
}

int gradeCommand(const HmiOptions& o, ui::Language& language) {
    if (!o.verdict.empty()) {
        if (auto refused = ui::refusedVerdictOutput(QString::fromStdString(o.verdict), QString::fromStdString(o.attempt),
                                                    QString::fromStdString(o.exercise))) {
            return refuse(*refused);
        }
    }
    ui::GradeRequest request;
    request.exerciseFolder = QString::fromStdString(o.exercise);
    request.attemptFile = QString::fromStdString(o.attempt);
    if (!o.exam.empty()) {
        training::Exam exam;
        if (auto refused = readExamOption(o.exam, language, &exam)) {
            return refuse(QString::fromStdString(*refused));
        }
        request.examKey = QByteArray::fromStdString(exam.key);
        request.requireChain = true;
    }
    request.language = &language;
    const ui::GradeOutcome outcome = ui::gradeAttemptFile(request);
    if (!outcome.verdict) {
        return refuse(outcome.error);
    }
    const training::Verdict& verdict = *outcome.verdict;
    const MessageLanguage said = language.current() == QLatin1String("en") ? MessageLanguage::English : MessageLanguage::Chinese;
    for (const training::CheckResult& check : verdict.checks) {
        std::printf("%s %s: %s (%s)%s%s\n", check.passed ? "PASS" : "FAIL", check.id.c_str(), check.measured.c_str(),
                    check.expected.c_str(), check.passed ? "" : " - ", check.passed ? "" : check.reason.in(said).c_str());
    }
    std::printf("%s %s: %d/100, %.1f s%s\n", verdict.passed ? "PASSED" : "FAILED", verdict.exercise.c_str(), verdict.score,
                verdict.timeUsed, verdict.timedOut ? " (time out)" : "");
    if (!o.verdict.empty()) {
        if (auto error = writeOutput(o.verdict, QByteArray::fromStdString(training::verdictJson(verdict)))) {
            return refuse(QStringLiteral("--verdict: %1").arg(*error));
        }
    }
    return verdict.passed ? 0 : 1;
}

} // namespace m350::hmi
