// A recording made while 试切 (MPG RUN) guides a run: its times only grow, so it replays, and the
// replay takes the machine where the session took it.
#include "tests/ui/PanelHarness.h"

namespace m350::test {

TEST(TryCutRecording, ARecordedHandwheelGuidedRunReplays) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("try-cut.jsonl"));
    PanelHarness panel;
    QString error;
    ASSERT_TRUE(panel.window().startRecording(path, &error)) << error.toStdString();
    panel.key("MPG_RUN");
    panel.key("MDI");
    panel.type("G91 G1 X200 F1200");
    panel.key("ENTER");
    panel.softkey(1);
    panel.advance(0.5);
    auto x = [](PanelHarness& p) { return p.session().latest()->status.machine(0); };
    panel.turnWheel(0, 10, 2, 1.0);  // forward: 顺切
    panel.advance(1.0);               // the wheel stands: the display time stands too
    panel.turnWheel(0, 10, -2, 0.5); // backwards: 逆切 retraces, the display time runs back
    panel.advance(1.0);
    panel.turnWheel(0, 10, 2, 0.5);
    panel.advance(2.0);
    const double end = x(panel);
    const double sessionEnd = panel.session().latest()->sessionTime;
    EXPECT_GT(end, 5.0) << "the wheel moved the program";

    auto actions = ui::readReplay(path, &error);
    ASSERT_TRUE(actions) << error.toStdString();
    ASSERT_GT(actions->size(), 100u) << "every wheel turn is in it";
    double previous = 0.0;
    bool backwards = false;
    for (const ui::OperatorAction& action : *actions) {
        EXPECT_GE(action.t, previous);
        previous = action.t;
        backwards = backwards || (action.kind == ui::OperatorAction::Kind::Wheel && action.wheel.detents < 0);
    }
    EXPECT_TRUE(backwards) << "the backward turn is recorded";

    PanelHarness again;
    ui::playReplay(again.window(), again.session(), *actions);
    again.advance(sessionEnd - actions->back().t);
    auto replayed = again.session().latest();
    EXPECT_TRUE(replayed->status.guide) << "the replay is in 试切";
    EXPECT_GT(x(again), 0.01) << "its wheel turns drive the program";
    EXPECT_NEAR(x(again), end, 0.01) << "the replay takes the machine where the session took it";
}

} // namespace m350::test
