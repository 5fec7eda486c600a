// Every bundled exercise (resources/exercises/NAME) loads, and each of its recorded attempts
// (tests/training/attempts/NAME/*.jsonl) is graded as its first line says: `// passes` for the
// correct one, `// fails: id id ...` for a wrong one, naming exactly the checks that fail (the
// check that names its mistake among them). Graded headless through m350-hmi --exercise --attempt,
// as a trainer grades a class, with the exit status and the verdict JSON checked.
#include "core/config/MachineConfig.h"
#include "core/training/ExerciseFile.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <variant>

namespace m350::test {

namespace {

const QString kExercises = QStringLiteral(M350_SOURCE_DIR "/resources/exercises");
const QString kAttempts = QStringLiteral(M350_SOURCE_DIR "/tests/training/attempts");

struct Expected {
    bool passes = false;
    std::set<std::string> failing;
};

// The attempt's first line: "// passes" or "// fails: a b c".
Expected expectedOf(const QString& attempt) {
    QFile file(attempt);
    Expected out;
    if (!file.open(QIODevice::ReadOnly)) {
        return out;
    }
    const QString first = QString::fromUtf8(file.readLine()).trimmed();
    if (first == QLatin1String("// passes")) {
        out.passes = true;
    } else if (first.startsWith(QLatin1String("// fails:"))) {
        for (const QString& id : first.mid(9).split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
            out.failing.insert(id.toStdString());
        }
    }
    return out;
}

struct Graded {
    int exitCode = -1;
    QString output;
    QJsonObject verdict;
};

// m350-hmi offscreen with `arguments`; its exit status and what it printed.
std::pair<int, QString> hmiOutput(const QStringList& arguments) {
    QProcess hmi;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    hmi.setProcessEnvironment(env);
    hmi.start(QStringLiteral(M350_HMI_PATH), arguments);
    if (!hmi.waitForFinished(120000)) {
        hmi.kill();
        return {-1, QStringLiteral("m350-hmi did not finish")};
    }
    return {hmi.exitCode(), QString::fromUtf8(hmi.readAllStandardOutput() + hmi.readAllStandardError())};
}

Graded grade(const QString& exercise, const QString& attempt, const QStringList& extra = {}) {
    QTemporaryDir dir;
    const QString verdict = dir.filePath(QStringLiteral("verdict.json"));
    Graded out;
    std::tie(out.exitCode, out.output) =
        hmiOutput(QStringList{QStringLiteral("--lang"), QStringLiteral("en"), QStringLiteral("--exercise"), exercise,
                           QStringLiteral("--attempt"), attempt, QStringLiteral("--verdict"), verdict} +
               extra);
    QFile file(verdict);
    if (file.open(QIODevice::ReadOnly)) {
        out.verdict = QJsonDocument::fromJson(file.readAll()).object();
    }
    return out;
}

// An exam file with the empty key (the training's attempts outside an exam are chained with it).
QString emptyKeyExam(const QString& folder) {
    const QString path = folder + QStringLiteral("/exam.toml");
    QFile file(path);
    if (file.open(QIODevice::WriteOnly)) {
        file.write("exercises = [\"any\"]\nkey = \"\"\n");
    }
    return path;
}

// The attempt played through m350-hmi --training (the panel's training mode): its --state.
QJsonObject trainingRun(const QString& exercise, const QString& attempt, const QString& attempts) {
    QTemporaryDir dir;
    const QString state = dir.filePath(QStringLiteral("state.json"));
    const auto [status, output] =
        hmiOutput({QStringLiteral("--lang"), QStringLiteral("en"), QStringLiteral("--training"), QStringLiteral("--trainee"),
                QStringLiteral("test"), QStringLiteral("--attempts"), attempts, QStringLiteral("--exercise"), exercise,
                QStringLiteral("--replay"), attempt, QStringLiteral("--state"), state});
    QFile file(state);
    if (!file.open(QIODevice::ReadOnly)) {
        return QJsonObject{{QStringLiteral("error"), output}, {QStringLiteral("status"), status}};
    }
    return QJsonDocument::fromJson(file.readAll()).object();
}

QStringList exerciseNames() {
    return QDir(kExercises).entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name);
}

} // namespace

TEST(TrainingExercises, EveryBundledExerciseLoads) {
    const QStringList names = exerciseNames();
    ASSERT_FALSE(names.isEmpty());
    for (const QString& name : names) {
        SCOPED_TRACE(name.toStdString());
        auto loaded = training::loadExercise((kExercises + QLatin1Char('/') + name).toStdString(),
                                             config::bundledMachinesDirectory());
        if (auto* error = std::get_if<training::ExerciseError>(&loaded)) {
            ADD_FAILURE() << error->where() << ": " << error->words.english();
            continue;
        }
        const auto& exercise = std::get<training::Exercise>(loaded);
        EXPECT_FALSE(exercise.title.chinese.empty());
        EXPECT_FALSE(exercise.task.english.empty());
        const QStringList attempts =
            QDir(kAttempts + QLatin1Char('/') + name).entryList(QStringList{QStringLiteral("*.jsonl")}, QDir::Files);
        int correct = 0;
        int wrong = 0;
        for (const QString& attempt : attempts) {
            const Expected expected = expectedOf(kAttempts + QLatin1Char('/') + name + QLatin1Char('/') + attempt);
            correct += expected.passes;
            wrong += !expected.passes && !expected.failing.empty();
        }
        EXPECT_GE(correct, 1) << "a recorded correct attempt";
        EXPECT_GE(wrong, 2) << "at least two recorded wrong attempts, each naming the checks it fails";
    }
}

class ExerciseAttempt : public testing::TestWithParam<std::string> {};

TEST_P(ExerciseAttempt, IsGradedAsItsFirstLineSays) {
    const QString name = QString::fromStdString(GetParam());
    const QString exercise = kExercises + QLatin1Char('/') + name;
    const QStringList attempts =
        QDir(kAttempts + QLatin1Char('/') + name).entryList(QStringList{QStringLiteral("*.jsonl")}, QDir::Files);
    for (const QString& attempt : attempts) {
        SCOPED_TRACE(attempt.toStdString());
        const QString path = kAttempts + QLatin1Char('/') + name + QLatin1Char('/') + attempt;
        const Expected expected = expectedOf(path);
        const Graded graded = grade(exercise, path);
        ASSERT_EQ(graded.exitCode, expected.passes ? 0 : 1) << graded.output.toStdString();
        EXPECT_EQ(graded.verdict.value(QStringLiteral("passed")).toBool(), expected.passes);
        std::set<std::string> failing;
        for (const QJsonValue& check : graded.verdict.value(QStringLiteral("checks")).toArray()) {
            const QJsonObject c = check.toObject();
            if (!c.value(QStringLiteral("passed")).toBool()) {
                failing.insert(c.value(QStringLiteral("id")).toString().toStdString());
                EXPECT_FALSE(c.value(QStringLiteral("reason")).toObject().value(QStringLiteral("zh_CN")).toString().isEmpty());
            }
        }
        EXPECT_EQ(failing, expected.failing) << graded.output.toStdString();

        // the same attempt through the training's panel: the same verdict, check by check, and the
        // attempt it recorded is chained and grades the same headless
        QTemporaryDir attempts;
        const QJsonObject panel = trainingRun(exercise, path, attempts.path());
        ASSERT_EQ(panel.value(QStringLiteral("page")).toString(), QStringLiteral("verdict")) << QJsonDocument(panel).toJson().toStdString();
        EXPECT_EQ(panel.value(QStringLiteral("passed")).toBool(), expected.passes);
        const QJsonArray headless = graded.verdict.value(QStringLiteral("checks")).toArray();
        const QJsonArray inPanel = panel.value(QStringLiteral("checks")).toArray();
        ASSERT_EQ(inPanel.size(), headless.size());
        for (qsizetype i = 0; i < headless.size(); ++i) {
            for (const char* field : {"id", "passed", "measured", "expected"}) {
                EXPECT_EQ(inPanel[i].toObject().value(QLatin1String(field)), headless[i].toObject().value(QLatin1String(field)))
                    << field << " of " << headless[i].toObject().value(QStringLiteral("id")).toString().toStdString();
            }
        }
        const Graded recorded = grade(exercise, panel.value(QStringLiteral("attempt_file")).toString(),
                                      QStringList{QStringLiteral("--exam"), emptyKeyExam(attempts.path())});
        EXPECT_EQ(recorded.exitCode, expected.passes ? 0 : 1) << recorded.output.toStdString();
    }
}

INSTANTIATE_TEST_SUITE_P(Bundled, ExerciseAttempt, testing::ValuesIn([] {
                             std::vector<std::string> names;
                             for (const QString& name : exerciseNames()) {
                                 names.push_back(name.toStdString());
                             }
                             return names;
                         }()),
                         [](const testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param;
                             for (char& c : name) {
                                 c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                             }
                             return name;
                         });

} // namespace m350::test

namespace m350::test {

// An exam takes only attempts the panel recorded in it: a hand-made attempt (no chain) and a
// recorded one edited afterwards are refused with exit 2, naming the line.
TEST(TrainingExam, TheGraderRefusesAnUnchainedOrEditedAttempt) {
    const QString exercise = kExercises + QStringLiteral("/pocket-taught-off");
    const QString handMade = kAttempts + QStringLiteral("/pocket-taught-off/correct.jsonl");
    QTemporaryDir attempts;
    const QString exam = emptyKeyExam(attempts.path());
    const Graded unchained = grade(exercise, handMade, {QStringLiteral("--exam"), exam});
    EXPECT_EQ(unchained.exitCode, 2);
    EXPECT_TRUE(unchained.output.contains(QStringLiteral("carries no hash chain"))) << unchained.output.toStdString();

    const QJsonObject panel = trainingRun(exercise, handMade, attempts.path());
    const QString recorded = panel.value(QStringLiteral("attempt_file")).toString();
    ASSERT_FALSE(recorded.isEmpty());
    EXPECT_EQ(grade(exercise, recorded, {QStringLiteral("--exam"), exam}).exitCode, 0);
    QFile file(recorded);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    QByteArray text = file.readAll();
    file.close();
    ASSERT_TRUE(text.contains("\"text\":\"110\""));
    text.replace("\"text\":\"110\"", "\"text\":\"111\"");
    ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(text);
    file.close();
    const Graded edited = grade(exercise, recorded, {QStringLiteral("--exam"), exam});
    EXPECT_EQ(edited.exitCode, 2);
    EXPECT_TRUE(edited.output.contains(QStringLiteral("does not follow the chain"))) << edited.output.toStdString();
}

} // namespace m350::test

namespace m350::test {

// --review without --exercise opens the exercise the attempt's first line names (bundled).
TEST(TrainingReviewCommand, FindsTheExerciseTheAttemptNames) {
    QTemporaryDir dir;
    const QString state = dir.filePath(QStringLiteral("state.json"));
    const auto [status, output] =
        hmiOutput({QStringLiteral("--lang"), QStringLiteral("en"), QStringLiteral("--review"),
                   kAttempts + QStringLiteral("/pocket-taught-off/correct.jsonl"), QStringLiteral("--state"), state});
    ASSERT_EQ(status, 0) << output.toStdString();
    QFile file(state);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_TRUE(QJsonDocument::fromJson(file.readAll()).object().value(QStringLiteral("passed")).toBool());
    QFile unnamed(dir.filePath(QStringLiteral("unnamed.jsonl")));
    ASSERT_TRUE(unnamed.open(QIODevice::WriteOnly));
    unnamed.write("{\"t\":1,\"key\":\"START\"}\n");
    unnamed.close();
    const auto [refused, why] = hmiOutput({QStringLiteral("--lang"), QStringLiteral("en"), QStringLiteral("--review"), unnamed.fileName(),
                                           QStringLiteral("--state"), state});
    EXPECT_EQ(refused, 2);
    EXPECT_TRUE(why.contains(QStringLiteral("names no exercise"))) << why.toStdString();
}

} // namespace m350::test
