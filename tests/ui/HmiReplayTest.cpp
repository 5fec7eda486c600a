// m350-hmi --replay as a user runs it: the recorded actions play in virtual time, then the
// screenshot and the panel's state are written.
#include <QDir>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include "tests/bench/ReplayMix.h"

#include <gtest/gtest.h>

namespace m350::test {

namespace {

struct HmiRun {
    int exitCode = -1;
    QString errors;
    QJsonObject state;
    QImage screenshot;
};

HmiRun runHmi(const QStringList& arguments, int timeoutMs = 60000) {
    QTemporaryDir dir;
    QString state = dir.filePath("state.json");
    QString png = dir.filePath("screen.png");
    QProcess hmi;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("QT_QPA_PLATFORM", "offscreen");
    hmi.setProcessEnvironment(env);
    hmi.start(M350_HMI_PATH, arguments + QStringList{"--state", state, "--screenshot", png});
    HmiRun run;
    if (!hmi.waitForFinished(timeoutMs)) {
        hmi.kill();
        run.errors = QStringLiteral("m350-hmi did not finish within %1 s").arg(timeoutMs / 1000);
        return run;
    }
    run.exitCode = hmi.exitCode();
    run.errors = QString::fromUtf8(hmi.readAllStandardError());
    QFile file(state);
    if (file.open(QIODevice::ReadOnly)) {
        run.state = QJsonDocument::fromJson(file.readAll()).object();
    }
    run.screenshot.load(png);
    return run;
}

QString replay(const char* name) { return QDir(M350_REPLAY_DIR).filePath(QString::fromLatin1(name)); }


// Pixels that differ between two screenshots of one size, the status line's clock aside (the wall
// clock's time, at its right end); `first` names the first one.
int differingPixels(const QImage& fast, const QImage& eager, QString* first) {
    if (fast.isNull() || fast.size() != eager.size()) {
        *first = QStringLiteral("no screenshot or sizes differ");
        return -1;
    }
    const QImage a = fast.convertToFormat(QImage::Format_RGB32);
    const QImage b = eager.convertToFormat(QImage::Format_RGB32);
    int different = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            const bool clock = y >= 20 && y < 50 && x >= a.width() / 2;
            if (!clock && a.pixel(x, y) != b.pixel(x, y)) {
                *first = first->isEmpty() ? QStringLiteral("%1,%2").arg(x).arg(y) : *first;
                ++different;
            }
        }
    }
    return different;
}

// Two runs of one replay end alike: the same --state but the work record's start date (the wall
// clock's: the one field two runs never share), every pixel the same but the status line's clock.
void expectSameEnd(const HmiRun& fast, const HmiRun& eager) {
    QJsonObject fastState = fast.state;
    QJsonObject eagerState = eager.state;
    fastState.remove("work_record");
    eagerState.remove("work_record");
    EXPECT_EQ(QJsonDocument(fastState).toJson().toStdString(), QJsonDocument(eagerState).toJson().toStdString());
    QString first;
    EXPECT_EQ(differingPixels(fast.screenshot, eager.screenshot, &first), 0) << "first at " << first.toStdString();
}

} // namespace

TEST(HmiReplay, MdiLineRunsAndTheStateShowsWhereTheMachineIs) {
    HmiRun run = runHmi({"--replay", replay("mdi-move.jsonl")});
    ASSERT_EQ(run.exitCode, 0) << run.errors.toStdString();
    EXPECT_EQ(run.state["page"].toString(), "mdi");
    EXPECT_NEAR(run.state["work"].toObject()["X"].toDouble(), 10.0, 1e-6);
    EXPECT_NEAR(run.state["work"].toObject()["Y"].toDouble(), 20.0, 1e-6);
    EXPECT_EQ(run.state["mdi_lines"].toArray().at(0).toString(), "G90 G0 X10 Y20");
    EXPECT_EQ(run.state["state"].toString(), "READY");
    EXPECT_FALSE(run.screenshot.isNull());
    EXPECT_EQ(run.screenshot.size(), QSize(1024, 600));
}

TEST(HmiReplay, OutOpenSwitchesTheDrawbarOutput) {
    // an empty spindle: releasing the drawbar over nothing with a tool in it would drop the tool
    HmiRun run = runHmi({"--replay", replay("io-output.jsonl"), "--tool", "0"});
    ASSERT_EQ(run.exitCode, 0) << run.errors.toStdString();
    EXPECT_EQ(run.state["page"].toString(), "io");
    EXPECT_EQ(run.state["io_selected"].toInt(), 750);
    EXPECT_EQ(run.state["outputs"].toArray().at(0).toInt(), 1);
    EXPECT_EQ(run.state["inputs"].toArray().at(10).toInt(), 1) << "the clamp cylinder answers on IN11";
}

TEST(HmiReplay, AStuckSensorDuringT2EndsInTheWatchdogAlarm) {
    HmiRun run = runHmi({"--replay", replay("stuck-sensor-t2.jsonl")});
    ASSERT_EQ(run.exitCode, 0) << run.errors.toStdString();
    QJsonObject alarm = run.state["alarm"].toObject();
    EXPECT_EQ(alarm["code"].toString(), "sensor_timeout");
    EXPECT_TRUE(alarm["message"].toString().contains("IN11")) << alarm["message"].toString().toStdString();
    EXPECT_EQ(run.state["state"].toString(), "ERROR");
    // T1 stood in its fork with the drawbar released when IN11 timed out: the safe state clamps the
    // drawbar on it, so the spindle holds T1 again, and T2 was never fetched
    EXPECT_EQ(run.state["tool"].toInt(), 1);
}

TEST(HmiReplay, AnEStopInT2ThenT3EndsInTheToolNumberPrompt) {
    for (const char* lang : {"zh_CN", "en"}) {
        HmiRun run = runHmi({"--replay", replay("estop-in-tool-change.jsonl"), "--lang", lang});
        ASSERT_EQ(run.exitCode, 0) << lang << ": " << run.errors.toStdString();
        EXPECT_TRUE(run.state["tool_unsure"].toBool()) << lang;
        EXPECT_EQ(run.state["alarm"].toObject()["code"].toString(), "invalid_argument") << lang;
        const QString prompt = run.state["prompt"].toString();
        const bool zh = QLatin1String(lang) == QLatin1String("zh_CN");
        EXPECT_TRUE(prompt.contains(zh ? QStringLiteral("设置目标刀具号") : QStringLiteral("Set target tool No.:")))
            << lang << ": " << prompt.toStdString();
        EXPECT_TRUE(prompt.contains(zh ? QStringLiteral("请手动处理") : QStringLiteral("handle it by hand")))
            << lang << ": " << prompt.toStdString();
        EXPECT_TRUE(run.state["alarm_text"].toString().contains(zh ? QStringLiteral("输入主轴上的刀号之前不能换刀")
                                                                   : QStringLiteral("No tool change before")))
            << lang << ": " << run.state["alarm_text"].toString().toStdString();
        EXPECT_FALSE(run.screenshot.isNull());
    }
}

TEST(HmiReplay, TheHandwheelGuideStopsWhenTheWheelStops) {
    HmiRun run = runHmi({"--replay", replay("handwheel-guide.jsonl")});
    ASSERT_EQ(run.exitCode, 0) << run.errors.toStdString();
    EXPECT_EQ(run.state["mode"].toString(), "WHEEL");
    EXPECT_TRUE(run.state["guide"].toBool());
    double x = run.state["work"].toObject()["X"].toDouble();
    EXPECT_GT(x, -300.0 + 0.5) << "the wheel moved the program";
    EXPECT_LT(x, -300.0 + 100.0) << "it stopped short of the end when the wheel stopped";
    EXPECT_EQ(run.state["run"].toString(), "running");
}

TEST(HmiReplay, ABadReplayFileIsRefusedWithItsLine) {
    QTemporaryDir dir;
    QString bad = dir.filePath("bad.jsonl");
    QFile file(bad);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("{\"t\":0,\"key\":\"MDI\"}\n{\"t\":1,\"wheel\":{\"axis\":\"X\",\"step\":3,\"detents\":1}}\n");
    file.close();
    HmiRun run = runHmi({"--replay", bad, "--lang", "en"});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.errors.contains("bad.jsonl:2:8: wheel step must be 1, 10 or 100")) << run.errors.toStdString();
    HmiRun zh = runHmi({"--replay", bad}); // the panel's language
    EXPECT_TRUE(zh.errors.contains("bad.jsonl:2:8: 手轮倍率须为 1、10 或 100")) << zh.errors.toStdString();
}

TEST(HmiReplay, EveryPageRendersInBothLanguages) {
    for (const char* page : {"monitor", "mdi", "io", "probe", "program", "param", "log", "system", "coord", "middle",
                             "record", "breakrun", "tools", "toollife", "breakage", "custom"}) {
        for (const char* lang : {"zh_CN", "en"}) {
            HmiRun run = runHmi({"--page", page, "--lang", lang});
            ASSERT_EQ(run.exitCode, 0) << page << " " << lang << ": " << run.errors.toStdString();
            EXPECT_EQ(run.state["page"].toString(), QString::fromLatin1(page));
            EXPECT_EQ(run.state["language"].toString(), QString::fromLatin1(lang));
            EXPECT_FALSE(run.screenshot.isNull());
        }
    }
}

} // namespace m350::test

namespace m350::test {

TEST(HmiReplay, FixedToolSettingStoresTheTripHeightInParam930) {
    HmiRun run = runHmi({"--replay", replay("fixed-tool-setting.jsonl")});
    ASSERT_EQ(run.exitCode, 0) << run.errors.toStdString();
    EXPECT_EQ(run.state["page"].toString(), "probe");
    EXPECT_TRUE(run.state["alarm"].isNull()) << run.state["alarm_text"].toString().toStdString();
    EXPECT_TRUE(run.state["status_message"].toString().contains(QStringLiteral("对刀完成")))
        << run.state["status_message"].toString().toStdString();
    EXPECT_TRUE(run.state["probe_offsets"].toArray().at(0).toString().contains("-53.677"))
        << run.state["probe_offsets"].toArray().at(0).toString().toStdString();
}

TEST(HmiReplay, SwitchingToEnglishChangesTheWords) {
    HmiRun zh = runHmi({"--page", "mdi"});
    HmiRun en = runHmi({"--replay", replay("language-switch.jsonl")});
    ASSERT_EQ(en.exitCode, 0) << en.errors.toStdString();
    EXPECT_EQ(zh.state["language"].toString(), "zh_CN");
    EXPECT_EQ(en.state["language"].toString(), "en");
    EXPECT_EQ(en.state["mdi_lines"].toArray().at(0).toString(), "G0 X1");
    EXPECT_EQ(en.state["softkeys"].toArray().at(0).toString(), "F1 Execute(1)");
    EXPECT_EQ(zh.state["softkeys"].toArray().at(0).toString(), QStringLiteral("F1 执行(1)"));
}

TEST(HmiReplay, AParameterEditAtGuestLevelAsksForThePasswordAndRefusesAnOutOfRangeValue) {
    HmiRun run = runHmi({"--replay", replay("param-level-edit.jsonl")});
    ASSERT_EQ(run.exitCode, 0) << run.errors.toStdString();
    EXPECT_EQ(run.state["page"].toString(), "param");
    EXPECT_EQ(run.state["user_level"].toString(), "operator");
    EXPECT_EQ(run.state["param_selected"].toInt(), 129);
    EXPECT_EQ(run.state["param_value"].toString(), "12.500") << "150 was refused, 12.5 taken";
}

TEST(HmiReplay, ASimulationTypedInTheEditorRunsBesideTheMachine) {
    HmiRun run = runHmi({"--replay", replay("program-simulation.jsonl")});
    ASSERT_EQ(run.exitCode, 0) << run.errors.toStdString();
    EXPECT_EQ(run.state["page"].toString(), "program");
    EXPECT_EQ(run.state["program_mode"].toString(), "simulation");
    EXPECT_EQ(run.state["mode"].toString(), "SL");
    EXPECT_EQ(run.state["state"].toString(), "BUSY");
    EXPECT_GE(run.state["simulation_line"].toInt(), 3);
    EXPECT_GT(run.state["simulation_points"].toInt(), 50); // the arcs in chords
    for (const char* axis : {"X", "Y", "Z"}) {
        EXPECT_EQ(run.state["machine"].toObject()[axis].toDouble(), 0.0) << axis; // the machine never moved
    }
}

TEST(HmiReplay, PauseResetAndPauseResumeFinishTheProgramWhereAnUninterruptedRunEnds) {
    HmiRun run = runHmi({"--lang", "en", "--replay", replay("break-run.jsonl")});
    ASSERT_EQ(run.exitCode, 0) << run.errors.toStdString();
    EXPECT_EQ(run.state["page"].toString(), "breakrun");
    EXPECT_EQ(run.state["state"].toString(), "READY");
    EXPECT_NEAR(run.state["work"].toObject()["X"].toDouble(), 60.0, 1e-6);
    EXPECT_NEAR(run.state["work"].toObject()["Y"].toDouble(), 40.0, 1e-6);
    EXPECT_TRUE(run.state["alarm"].isNull());
    EXPECT_TRUE(run.state["break_points"].toString().contains("brk.nc L:5")) << run.state["break_points"].toString().toStdString();
}

TEST(HmiReplay, TouchOffFromTheToolTableRewritesTheLoadedToolsZ) {
    HmiRun run = runHmi({"--replay", replay("tool-table-touch-off.jsonl")});
    ASSERT_EQ(run.exitCode, 0) << run.errors.toStdString();
    EXPECT_EQ(run.state["page"].toString(), "tools");
    const QJsonArray rows = run.state["tool_table"].toArray();
    ASSERT_GE(rows.size(), 2);
    // T1 in the spindle at machine Z 0, G54 Z -12.5: Z offset = 0 - (-12.5) - 2 = 10.5
    EXPECT_EQ(rows.at(0).toString(), QStringLiteral("T1 P1 Z10.5")) << rows.at(0).toString().toStdString();
    EXPECT_EQ(rows.at(1).toString(), QStringLiteral("T2 P2 Z-48.12 ;{teeth=3}"));
    EXPECT_EQ(run.state["tool_table_selected"].toInt(), 2);
}

} // namespace m350::test

namespace m350::test {

// The 刀具寿命 view's replay (docs/replays/toollife.jsonl, its program written here): G10 L3 enters
// the groups, T6 cuts 70 s of its 1 minute, the next T102 brings in T7, and the view, opened through
// 刀具表's Shift+F1, shows T6 spent and T7 in use.
TEST(HmiReplay, ToolLifeViewShowsTheSisterAProgramBroughtIn) {
    QTemporaryDir dir;
    QFile program(dir.filePath("life.nc"));
    ASSERT_TRUE(program.open(QIODevice::WriteOnly));
    program.write("G10 L3\nP2 L1 Q2\nT6 H6\nT7 H7\nG11\nT102\nG90 G54 G0 X10 Y10\nG91 G1 X50 F300\nX-50\nX50\n"
                  "X-50\nX50\nX-50\nX50\nT102\nM30\n");
    program.close();
    QFile replayFile(dir.filePath("life.jsonl"));
    ASSERT_TRUE(replayFile.open(QIODevice::WriteOnly));
    replayFile.write(QStringLiteral("{\"t\":0,\"load\":\"%1\"}\n{\"t\":0.1,\"key\":\"START\"}\n"
                                    "{\"t\":150,\"page\":\"probe\"}\n{\"t\":150.1,\"softkey\":2}\n"
                                    "{\"t\":150.2,\"softkey\":7}\n")
                         .arg(program.fileName())
                         .toUtf8());
    replayFile.close();
    // the program's folder is the U disk: a replay loads only what the Program page shows
    HmiRun run = runHmi({"--replay", replayFile.fileName(), "--lang", "en", "--programs", dir.path()});
    ASSERT_EQ(run.exitCode, 0) << run.errors.toStdString();
    EXPECT_EQ(run.state["page"].toString(), "toollife");
    const QJsonArray rows = run.state["tool_life"].toArray();
    ASSERT_EQ(rows.size(), 2);
    EXPECT_EQ(rows.at(0).toString(), "2|Minutes|1:00|T6|6|0|1:08|0:00|# Life reached") << "17 units of 4 s";
    EXPECT_EQ(rows.at(1).toString(), "|||T7|7|0|0:00|1:00|@ In use");
}

} // namespace m350::test

namespace m350::test {

// A long replay of real actions (tests/bench/ReplayMix.h: page switches, softkeys, jog taps in STEP
// mode, overrides, wheel clicks, MDI lines, two program runs) ends the same played fast (the panel
// laid out only where an action reads it, the machine in the panel's thread) as played the way
// m350-hmi played every replay before (--eager-replay): the same state, the same screenshot.
TEST(HmiReplay, ALongReplayOfRealActionsEndsAsTheEagerReplayEnds) {
    constexpr long kActions = 5000;
    QTemporaryDir dir;
    QFile program(dir.filePath("part.nc"));
    ASSERT_TRUE(program.open(QIODevice::WriteOnly));
    program.write(QByteArray::fromStdString(ReplayMix::programText()));
    program.close();
    QFile replayFile(dir.filePath("mix.jsonl"));
    ASSERT_TRUE(replayFile.open(QIODevice::WriteOnly));
    ReplayMix(7, program.fileName().toStdString()).write(kActions, [&replayFile](const std::string& line) {
        replayFile.write(QByteArray::fromStdString(line + "\n"));
    });
    replayFile.close();
    const QStringList arguments{"--replay", replayFile.fileName(), "--programs", dir.path(), "--lang", "en"};
    HmiRun fast = runHmi(arguments, 120000);
    HmiRun eager = runHmi(QStringList{"--eager-replay"} + arguments, 240000);
    ASSERT_EQ(fast.exitCode, 0) << fast.errors.toStdString();
    ASSERT_EQ(eager.exitCode, 0) << eager.errors.toStdString();

    // the replay did what it says: MDI lines kept, the program loaded, the machine moved and came back
    EXPECT_FALSE(fast.state["mdi_lines"].toArray().isEmpty());
    EXPECT_TRUE(fast.state["program"].toString().endsWith("part.nc")) << fast.state["program"].toString().toStdString();
    expectSameEnd(fast, eager);
}

// Lists scrolled far down between page switches (the System Log, the parameter table on two
// tabs, the IO ports) end where the eager replay leaves them: a fast replay that skipped a layout
// an action reads would scroll a table by the wrong height and show other rows.
TEST(HmiReplay, ListsScrolledBetweenPageSwitchesEndAsTheEagerReplayLeavesThem) {
    QTemporaryDir dir;
    QFile replayFile(dir.filePath("scroll.jsonl"));
    ASSERT_TRUE(replayFile.open(QIODevice::WriteOnly));
    double t = 0.0;
    auto step = [&](const QString& body) {
        t += 0.05;
        replayFile.write(QStringLiteral("{\"t\":%1,%2}\n").arg(t, 0, 'f', 2).arg(body).toUtf8());
    };
    auto keys = [&](const char* key, int times) {
        for (int i = 0; i < times; ++i) {
            step(QStringLiteral("\"key\":\"%1\"").arg(QLatin1String(key)));
        }
    };
    step(QStringLiteral("\"page\":\"log\""));
    keys("DOWN", 60);
    step(QStringLiteral("\"page\":\"param\""));
    keys("DOWN", 45);
    step(QStringLiteral("\"softkey\":8"));
    keys("DOWN", 30);
    keys("LOG", 1);
    keys("PARAM", 1);
    keys("UP", 7);
    step(QStringLiteral("\"page\":\"log\""));
    step(QStringLiteral("\"page\":\"io\""));
    keys("DOWN", 20);
    step(QStringLiteral("\"page\":\"param\""));
    replayFile.close();
    const QStringList arguments{"--replay", replayFile.fileName(), "--lang", "en"};
    HmiRun fast = runHmi(arguments);
    HmiRun eager = runHmi(QStringList{"--eager-replay"} + arguments);
    ASSERT_EQ(fast.exitCode, 0) << fast.errors.toStdString();
    ASSERT_EQ(eager.exitCode, 0) << eager.errors.toStdString();
    expectSameEnd(fast, eager);
}

// A headless replay's stderr carries what the panel says, not a platform note per page switch
// (the offscreen platform's "does not support propagateSizeHints()" came at every switch).
TEST(HmiReplay, PageSwitchesLeaveStderrQuiet) {
    QTemporaryDir dir;
    QFile replayFile(dir.filePath("pages.jsonl"));
    ASSERT_TRUE(replayFile.open(QIODevice::WriteOnly));
    const char* pages[] = {"MONITOR", "PARAM", "PROGRAM", "IO", "LOG", "SYSTEM", "MDI", "PROBE"};
    for (int i = 0; i < 80; ++i) {
        replayFile.write(QStringLiteral("{\"t\":%1,\"key\":\"%2\"}\n").arg(0.05 * i, 0, 'f', 2).arg(QLatin1String(pages[i % 8])).toUtf8());
    }
    replayFile.close();
    HmiRun run = runHmi({"--replay", replayFile.fileName(), "--lang", "en"});
    ASSERT_EQ(run.exitCode, 0) << run.errors.toStdString();
    EXPECT_FALSE(run.errors.contains("propagateSizeHints")) << run.errors.toStdString();
    EXPECT_LT(run.errors.count(QLatin1Char('\n')), 3) << run.errors.toStdString();
    EXPECT_EQ(run.state.value("page").toString(), QStringLiteral("probe"));
}

} // namespace m350::test
