#include "app/hmi/GradeCommand.h"

#include "app/hmi/HmiOutputs.h"
#include "ui/i18n/Language.h"
#include "core/training/Exam.h"
#include "ui/training/AttemptGrader.h"

#include <variant>

#include <cstdio>

namespace m350::hmi {


int gradeCommand(const HmiOptions& o, ui::Language& language) {
    if (!o.verdict.empty()) {
        if (auto refused = ui::refusedVerdictOutput(QString::fromStdString(o.verdict), QString::fromStdString(o.attempt),
                                                    QString::fromStdString(o.exercise))) {
            std::fprintf(stderr, "m350-hmi: %s\n", qPrintable(*refused));
            return 2;
        }
    }
    ui::GradeRequest request;
    request.exerciseFolder = QString::fromStdString(o.exercise);
    request.attemptFile = QString::fromStdString(o.attempt);
    if (!o.exam.empty()) {
        auto exam = training::loadExam(o.exam);
        if (auto* error = std::get_if<training::ExerciseError>(&exam)) {
            const MessageLanguage said = language.current() == QLatin1String("en") ? MessageLanguage::English : MessageLanguage::Chinese;
            std::fprintf(stderr, "m350-hmi: %s: %s\n", error->where().c_str(), error->words.in(said).c_str());
            return 2;
        }
        request.examKey = QByteArray::fromStdString(std::get<training::Exam>(exam).key);
        request.requireChain = true;
    }
    request.language = &language;
    const ui::GradeOutcome outcome = ui::gradeAttemptFile(request);
    if (!outcome.verdict) {
        std::fprintf(stderr, "m350-hmi: %s\n", qPrintable(outcome.error));
        return 2;
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
            std::fprintf(stderr, "m350-hmi: --verdict: %s\n", qPrintable(*error));
            return 2;
        }
    }
    return verdict.passed ? 0 : 1;
}

} // namespace m350::hmi
