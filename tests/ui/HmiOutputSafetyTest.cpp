// Issue 26, "Nothing lost": m350-hmi's own outputs (--state, --screenshot, --record, the Panel
// menu's recording) never land on the loaded program, the replay being played or the machine
// folder, a device is written as a device, a write that fails is an error; a replay loads only
// from the Program page's disks, stays within a day of virtual time, and says what is wrong where.
#include "tests/ui/PanelHarness.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <future>

namespace m350::test {

namespace {

struct HmiResult {
    int exitCode = -1;
    QString errors;
    qint64 ms = 0;
};

HmiResult hmi(const QStringList& arguments, const QString& workingDirectory, int timeoutMs = 60000) {
    QProcess process;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("QT_QPA_PLATFORM", "offscreen");
    process.setProcessEnvironment(env);
    process.setWorkingDirectory(workingDirectory);
    QElapsedTimer clock;
    clock.start();
    // the refusals are checked in English unless a test asks for the panel's zh_CN
    process.start(M350_HMI_PATH, arguments.contains("--lang") ? arguments : QStringList{"--lang", "en"} + arguments);
    HmiResult run;
    if (!process.waitForFinished(timeoutMs)) {
        process.kill();
        process.waitForFinished();
        run.errors = QStringLiteral("m350-hmi did not finish within %1 s").arg(timeoutMs / 1000);
        return run;
    }
    run.ms = clock.elapsed();
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    run.errors = QString::fromUtf8(process.readAllStandardError());
    return run;
}

QByteArray contents(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray("<missing>");
}

void write(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate)) << path.toStdString();
    file.write(bytes);
}

// A scratch folder with a machine (a copy of the bundled one), a program, a replay and notes.
class HmiOutputs : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(dir_.isValid());
        std::filesystem::copy(std::filesystem::path(M350_SOURCE_DIR) / "resources/machines/m350-linear16",
                              path("machine").toStdString(), std::filesystem::copy_options::recursive);
        write(path("prog.nc"), "G0 X1\nM30\n");
        write(path("replay.jsonl"), "{\"t\":0,\"key\":\"MDI\"}\n");
        write(path("notes.txt"), "my notes\n");
        params_ = contents(path("machine/params.toml"));
    }
    QString path(const QString& name) const { return dir_.filePath(name); }
    HmiResult run(const QStringList& arguments) { return hmi(arguments, dir_.path()); }
    // the refused run said so at exit 2 and left every file as it was
    void expectRefused(const HmiResult& r, const QString& says) {
        EXPECT_EQ(r.exitCode, 2) << r.errors.toStdString();
        EXPECT_TRUE(r.errors.contains(says)) << r.errors.toStdString();
        EXPECT_TRUE(r.errors.contains("refused, nothing was written")) << r.errors.toStdString();
        EXPECT_EQ(contents(path("prog.nc")), "G0 X1\nM30\n");
        EXPECT_EQ(contents(path("replay.jsonl")), "{\"t\":0,\"key\":\"MDI\"}\n");
        EXPECT_EQ(contents(path("notes.txt")), "my notes\n");
        EXPECT_EQ(contents(path("machine/params.toml")), params_);
    }

    QTemporaryDir dir_;
    QByteArray params_;
};

} // namespace

TEST_F(HmiOutputs, AnOutputOnTheProgramTheReplayOrTheMachineFolderIsRefused) {
    ASSERT_TRUE(QFile::link(path("prog.nc"), path("link.nc")));
    expectRefused(run({"--config", "machine", "--state", "machine/params.toml"}),
                  "--state machine/params.toml is inside the machine folder");
    // a machine folder named with `.` from inside it, a new file in it too
    HmiResult inside = hmi({"--config", ".", "--state", "params.toml"}, path("machine"));
    expectRefused(inside, "--state params.toml is inside the machine folder (.)");
    expectRefused(run({"--config", "machine", "--screenshot", "machine/new.png"}), "is inside the machine folder");
    expectRefused(run({"prog.nc", "--state", "link.nc"}), "--state link.nc is the loaded program (prog.nc)");
    expectRefused(run({"prog.nc", "--state", "./machine/../prog.nc"}), "is the loaded program");
    expectRefused(run({"--replay", "replay.jsonl", "--record", "replay.jsonl"}),
                  "--record replay.jsonl is the replay being played (replay.jsonl)");
    expectRefused(run({"--state", "out.json", "--screenshot", "out.json"}), "--screenshot out.json is also the --state file");
    EXPECT_FALSE(QFileInfo::exists(path("out.json")));
}

// The zh_CN panel (the default) says the refusal in Chinese, by message id as m350-sim does.
TEST_F(HmiOutputs, AnOutputOnAnInputIsRefusedInThePanelsLanguage) {
    HmiResult r = run({"--lang", "zh_CN", "prog.nc", "--state", "prog.nc"});
    EXPECT_EQ(r.exitCode, 2) << r.errors.toStdString();
    EXPECT_TRUE(r.errors.contains(QStringLiteral("--state prog.nc是已加载的程序（prog.nc）：已拒绝，未写入任何内容")))
        << r.errors.toStdString();
    r = run({"--lang", "zh_CN", "--config", "machine", "--record", "machine/r.jsonl"});
    EXPECT_TRUE(r.errors.contains(QStringLiteral("--record machine/r.jsonl位于机床文件夹（machine）内：已拒绝，未写入任何内容")))
        << r.errors.toStdString();
    EXPECT_EQ(contents(path("prog.nc")), "G0 X1\nM30\n");
}

TEST_F(HmiOutputs, AFolderAFileAsAFolderAndATextFileAsAScreenshotAreRefused) {
    ASSERT_TRUE(QDir(dir_.path()).mkdir("shots"));
    expectRefused(run({"--state", "shots"}), "--state shots: it is a folder, not a file");
    expectRefused(run({"--state", "notes.txt/state.json"}), "--state notes.txt/state.json: notes.txt is not a folder");
    expectRefused(run({"--state", "nowhere/state.json"}), "the folder nowhere does not exist");
    // it emptied the notes, then failed
    expectRefused(run({"--screenshot", "notes.txt"}), "--screenshot notes.txt: .txt is not an image format");
}

// Every refusal of an output and a machine folder that does not load are said in the panel's
// language (message ids, as m350-sim says them with --lang).
TEST_F(HmiOutputs, TheOtherRefusalsAndALoadErrorAreSaidInThePanelsLanguage) {
    ASSERT_TRUE(QDir(dir_.path()).mkdir("shots"));
    auto said = [this](const QStringList& arguments, const QString& text) {
        HmiResult r = run(QStringList{"--lang", "zh_CN"} + arguments);
        EXPECT_EQ(r.exitCode, 2) << r.errors.toStdString();
        EXPECT_TRUE(r.errors.contains(text)) << r.errors.toStdString();
    };
    said({"--state", "shots"}, QStringLiteral("--state shots：这是文件夹，不是文件：已拒绝，未写入任何内容"));
    said({"--state", "notes.txt/state.json"}, QStringLiteral("--state notes.txt/state.json：notes.txt不是文件夹"));
    said({"--state", "nowhere/state.json"}, QStringLiteral("文件夹nowhere不存在：已拒绝"));
    said({"--screenshot", "notes.txt"}, QStringLiteral("--screenshot notes.txt：.txt不是图像格式（"));
    said({"--state", "out.json", "--screenshot", "out.json"},
         QStringLiteral("--screenshot out.json也是--state的输出文件：已拒绝，未写入任何内容"));
    said({"--state", QString(250, QLatin1Char('s'))}, QStringLiteral("--state: 写入失败："));
    EXPECT_EQ(contents(path("notes.txt")), "my notes\n");

    write(path("machine/params.toml"), "[params]\n61 = = 3000\n");
    said({"--config", "machine"}, QStringLiteral("machine/params.toml:2:6: TOML 语法错误："));
    write(path("machine/params.toml"), "[params]\n61 = \"fast\"\n");
    said({"--config", "machine"}, QStringLiteral("machine/params.toml:2:6: '61'须为数值"));
    HmiResult english = run({"--config", "machine"});
    EXPECT_TRUE(english.errors.contains("machine/params.toml:2:6: '61' must be a number")) << english.errors.toStdString();
}

TEST_F(HmiOutputs, ARegularFileIsReplacedWholeThroughALinkAndAFifoIsWrittenAsAFifo) {
    write(path("state.json"), "old");
    ASSERT_TRUE(QFile::link(path("state.json"), path("state-link.json")));
    HmiResult replaced = run({"--state", "state-link.json", "--screenshot", "shot.jpg"});
    ASSERT_EQ(replaced.exitCode, 0) << replaced.errors.toStdString();
    EXPECT_TRUE(QFileInfo(path("state-link.json")).isSymLink()) << "the link stays a link";
    EXPECT_TRUE(QJsonDocument::fromJson(contents(path("state.json"))).object().contains("page"));
    EXPECT_TRUE(contents(path("shot.jpg")).startsWith("\xFF\xD8")) << "a JPEG for .jpg";
    EXPECT_TRUE(QDir(dir_.path()).entryList({".state*"}, QDir::Hidden | QDir::Files).isEmpty()) << "no temp file left";

    const QString fifo = path("state.fifo");
    ASSERT_EQ(::mkfifo(fifo.toLocal8Bit().constData(), 0600), 0);
    auto reader = std::async(std::launch::async, [fifo] { return contents(fifo); });
    HmiResult device = run({"--state", "state.fifo"});
    ASSERT_EQ(device.exitCode, 0) << device.errors.toStdString();
    ASSERT_EQ(reader.wait_for(std::chrono::seconds(30)), std::future_status::ready);
    EXPECT_TRUE(QJsonDocument::fromJson(reader.get()).object().contains("page"));
    struct stat s {};
    ASSERT_EQ(::stat(fifo.toLocal8Bit().constData(), &s), 0);
    EXPECT_TRUE(S_ISFIFO(s.st_mode)) << "written as a FIFO, not renamed over";
}

TEST_F(HmiOutputs, AWriteThatFailsIsAnErrorNotASuccess) {
    // a name the temp file beside it cannot have (NAME_MAX): the write fails after the run
    const QString name = QString(250, QLatin1Char('s'));
    HmiResult state = run({"--state", name});
    EXPECT_EQ(state.exitCode, 2) << state.errors.toStdString();
    EXPECT_TRUE(state.errors.contains("--state: " + name + ": cannot")) << state.errors.toStdString();
    HmiResult shot = run({"--screenshot", name + ".png"});
    EXPECT_EQ(shot.exitCode, 2) << shot.errors.toStdString();
    EXPECT_TRUE(shot.errors.contains("--screenshot: ")) << shot.errors.toStdString();
    HmiResult record = run({"--replay", "replay.jsonl", "--record", name});
    EXPECT_EQ(record.exitCode, 2) << record.errors.toStdString();
    EXPECT_TRUE(record.errors.contains("--record: " + name + ": cannot")) << record.errors.toStdString();
}

TEST_F(HmiOutputs, AReplayLoadsOnlyWhatTheProgramPageShows) {
    ASSERT_TRUE(QDir(dir_.path()).mkpath("disk"));
    write(path("secret.txt"), "SECRET LINE ONE\nSECRET LINE TWO\n");
    ASSERT_TRUE(QFile::link(path("secret.txt"), path("disk/secret.nc")));
    write(path("disk/ok.nc"), "G0 X1\nM30\n");
    for (const char* load : {"../../../../../../../../secret.txt", "disk/secret.nc", "disk/.hidden.nc"}) {
        write(path("load.jsonl"), QStringLiteral("{\"t\":0,\"key\":\"MDI\"}\n  {\"t\":0.5, \"load\":\"%1\"}\n")
                                      .arg(QString::fromLatin1(load))
                                      .toUtf8());
        HmiResult r = run({"--programs", "disk", "--replay", "load.jsonl", "--lang", "en", "--state", "s.json"});
        EXPECT_EQ(r.exitCode, 2) << load << ": " << r.errors.toStdString();
        EXPECT_TRUE(r.errors.contains(QStringLiteral("load.jsonl:2:13: load \"%1\": a replay loads only a program the "
                                                     "Program page shows")
                                          .arg(QString::fromLatin1(load))))
            << r.errors.toStdString();
        EXPECT_FALSE(r.errors.contains("SECRET")) << r.errors.toStdString();
    }
    write(path("load.jsonl"), "{\"t\":0,\"load\":\"disk/ok.nc\"}\n");
    HmiResult ok = run({"--programs", "disk", "--replay", "load.jsonl", "--state", "s.json"});
    ASSERT_EQ(ok.exitCode, 0) << ok.errors.toStdString();
    EXPECT_TRUE(QJsonDocument::fromJson(contents(path("s.json"))).object()["program"].toString().endsWith("ok.nc"))
        << contents(path("s.json")).toStdString();
}

TEST_F(HmiOutputs, AReplayErrorNamesItsLineColumnAndTheRealProblem) {
    const std::pair<const char*, const char*> cases[] = {
        {"{\"t\":0,\"frobnicate\":1}", "bad.jsonl:1:8: unknown action \"frobnicate\" (one of:"},
        {"{\"t\":0,\"key\":\"MDI\"", "bad.jsonl:1:19: missing '}' at the end of the line"},
        {"{\"t\":0,\"key\":\"MDI}", "bad.jsonl:1:14: unterminated string"},
        {"{\"t\":1e9}", "bad.jsonl:1:2: t = 1e+09 s is beyond the longest replay, 86400 s (24 h)"},
    };
    for (const auto& [line, says] : cases) {
        write(path("bad.jsonl"), QByteArray("{\"t\":0}\n") + line + "\n");
        HmiResult r = run({"--replay", "bad.jsonl", "--lang", "en"});
        EXPECT_EQ(r.exitCode, 2) << line;
        // the line is the second one
        QString expected = QString::fromLatin1(says).replace("bad.jsonl:1:", "bad.jsonl:2:");
        EXPECT_TRUE(r.errors.contains(expected)) << line << ": " << r.errors.toStdString();
        EXPECT_LT(r.ms, 30000) << line;
    }
    // and in the panel's own language, Chinese
    write(path("bad.jsonl"), "{\"t\":0,\"key\":\"MDI}\n");
    HmiResult zh = run({"--replay", "bad.jsonl", "--lang", "zh_CN"});
    EXPECT_EQ(zh.exitCode, 2);
    EXPECT_TRUE(zh.errors.contains(QStringLiteral("bad.jsonl:1:14: 字符串未结束"))) << zh.errors.toStdString();
}

// Two hours of virtual time with nothing happening: the machine sees every frame, the panel
// only the last, so it passes in seconds (it took minutes: 11 virtual seconds a wall second).
TEST_F(HmiOutputs, IdleVirtualTimePassesAtOnce) {
    write(path("idle.jsonl"), "{\"t\":0,\"key\":\"MDI\"}\n{\"t\":7200}\n");
    HmiResult r = hmi({"--replay", "idle.jsonl", "--state", "s.json"}, dir_.path(), 50000);
    ASSERT_EQ(r.exitCode, 0) << r.errors.toStdString();
    EXPECT_EQ(QJsonDocument::fromJson(contents(path("s.json"))).object()["page"].toString(), "mdi");
}

// The Panel menu's recording: never onto the loaded program or into the machine folder, and an
// old file stays whole until the first action replaces it.
TEST(PanelRecording, RefusesTheProgramAndTheMachineFolderAndReplacesAFileWhole) {
    PanelHarness panel;
    QTemporaryDir dir;
    panel.loadProgram("prog.nc", "G0 X1\nM30\n");
    const QString program = panel.session().latest()->programFile;
    ASSERT_FALSE(program.isEmpty());
    QString error;
    EXPECT_FALSE(panel.window().startRecording(program, &error));
    EXPECT_TRUE(error.contains(program)) << error.toStdString();
    EXPECT_EQ(contents(program), "G0 X1\nM30\n");
    const QString params = QDir(panel.folder()).filePath("params.toml");
    const QByteArray before = contents(params);
    EXPECT_FALSE(panel.window().startRecording(params, &error));
    EXPECT_TRUE(error.contains(panel.folder())) << error.toStdString();
    EXPECT_EQ(contents(params), before);

    const QString file = dir.filePath("session.jsonl");
    write(file, "an old recording\n");
    ASSERT_TRUE(panel.window().startRecording(file, &error)) << error.toStdString();
    EXPECT_EQ(contents(file), "an old recording\n") << "not truncated before there is something to write";
    panel.key("MDI");
    EXPECT_EQ(contents(file), "{\"key\":\"MDI\",\"t\":0}\n");
    EXPECT_EQ(panel.window().stopRecording(), QString());
}

} // namespace m350::test
