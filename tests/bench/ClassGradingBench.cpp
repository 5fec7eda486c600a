// A class's attempts graded headless (issue 28: 30 attempts in under 10 s in all): the bundled
// exercises' recorded attempts (tests/training/attempts), repeated until there are 30, graded
// in one process as m350-hmi --class-report does.
#include "core/training/ExerciseFile.h"
#include "ui/training/ClassReport.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QTemporaryDir>

#include <benchmark/benchmark.h>

namespace {

void BM_GradeClassOf30(benchmark::State& state) {
    QTemporaryDir folder;
    QStringList attempts;
    QDirIterator it(QStringLiteral(M350_SOURCE_DIR "/tests/training/attempts"), QStringList{QStringLiteral("*.jsonl")}, QDir::Files,
                    QDirIterator::Subdirectories);
    while (it.hasNext()) {
        attempts.append(it.next());
    }
    attempts.sort();
    if (attempts.isEmpty()) {
        state.SkipWithError("no recorded attempts");
        return;
    }
    for (int i = 0; i < 30; ++i) {
        const QString from = attempts[i % attempts.size()];
        const QString trainee = folder.filePath(QStringLiteral("trainee%1").arg(i));
        QDir().mkpath(trainee);
        QFile::copy(from, trainee + QLatin1Char('/') + QFileInfo(QFileInfo(from).absolutePath()).fileName() + QStringLiteral(".jsonl"));
    }
    const QString exercises = QString::fromStdString(m350::training::bundledExercisesDirectory());
    for (auto _ : state) {
        const m350::ui::ClassReport report = m350::ui::gradeClass(folder.path(), exercises, {}, false, nullptr);
        benchmark::DoNotOptimize(report.attempts.size());
        if (report.attempts.size() != 30) {
            state.SkipWithError("not every attempt was found");
        }
        for (const auto& attempt : report.attempts) {
            if (!attempt.verdict) {
                state.SkipWithError(attempt.error.toStdString().c_str());
                break;
            }
        }
    }
    state.counters["attempts"] = 30;
}
BENCHMARK(BM_GradeClassOf30)->Unit(benchmark::kMillisecond)->Iterations(1);

} // namespace
