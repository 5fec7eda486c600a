// Whether the machine could say anything new since its last snapshot: a replay skips the snapshot
// after an action on the screen alone, so the answer must turn false at every call that reaches
// the machine, and never be true with the machine in its own thread.
#include "tests/ui/PanelHarness.h"

namespace m350::test {

namespace {

// The machine in the panel's thread on a manual clock, as a headless replay runs it.
ui::MachineSession::Options inThePanelsThread() {
    ui::MachineSession::Options options;
    options.clock = ui::MachineSession::Clock::Manual;
    options.panelThread = true;
    return options;
}

} // namespace

TEST(SessionSnapshot, UnchangedOnlyUntilACallReachesTheMachineInThePanelsThread) {
    PanelHarness panel(inThePanelsThread());
    ui::settle(panel.session());
    EXPECT_TRUE(panel.session().unchangedSinceSnapshot());
    panel.page(QStringLiteral("param")); // the screen alone
    EXPECT_TRUE(panel.session().unchangedSinceSnapshot());
    panel.session().setJogStep(0.1); // reaches the machine: a snapshot now would say so
    EXPECT_FALSE(panel.session().unchangedSinceSnapshot());
    panel.session().sync();
    EXPECT_TRUE(panel.session().unchangedSinceSnapshot());
    panel.session().advance(1.0 / 60.0); // a frame passes and publishes
    EXPECT_TRUE(panel.session().unchangedSinceSnapshot());
    panel.key(QStringLiteral("FRO_UP"));
    EXPECT_TRUE(panel.session().unchangedSinceSnapshot()) << "settled: the key's snapshot came";
    panel.window().dispatcher().dispatch(ui::OperatorAction::key(QStringLiteral("FRO_DOWN")));
    EXPECT_FALSE(panel.session().unchangedSinceSnapshot()) << "the key's call is queued, not yet shown";
}

// In the panel's thread a call that ends in a snapshot of its own needs no second one from sync()
// (a replay syncs after every action on the machine); a sync with nothing run still publishes.
TEST(SessionSnapshot, SyncAfterACallThatPublishedPublishesNothingMore) {
    PanelHarness panel(inThePanelsThread());
    ui::settle(panel.session());
    int published = 0;
    QObject::connect(&panel.session(), &ui::MachineSession::snapshotReady, [&published] { ++published; });
    panel.session().setJogStep(0.1); // publishes when it runs
    panel.session().sync();
    QCoreApplication::sendPostedEvents();
    EXPECT_EQ(published, 1);
    EXPECT_TRUE(panel.session().unchangedSinceSnapshot());
    panel.session().sync(); // nothing ran: a snapshot all the same
    QCoreApplication::sendPostedEvents();
    EXPECT_EQ(published, 2);
}

TEST(SessionSnapshot, NeverUnchangedWithTheMachineInItsOwnThread) {
    ui::MachineSession::Options options;
    options.clock = ui::MachineSession::Clock::Manual;
    PanelHarness panel(options);
    ui::settle(panel.session());
    EXPECT_FALSE(panel.session().unchangedSinceSnapshot());
}

// The machine's scene (the 图形显示 view's drawing of it) is built for the snapshots only while the
// page shown draws the machine: built at every snapshot for nobody, it cost a replay a tenth of its
// time.
TEST(SessionSnapshot, CarriesTheMachinesSceneOnlyWhileAPageDrawsTheMachine) {
    PanelHarness panel;
    ui::settle(panel.session());
    EXPECT_FALSE(panel.session().latest()->scene) << "the Monitor draws no machine";
    panel.page(QStringLiteral("graphics"));
    ASSERT_TRUE(panel.session().latest()->scene);
    EXPECT_FALSE(panel.session().latest()->scene->magazine.pockets.empty());
    panel.page(QStringLiteral("program")); // its simulation draws the machine beside the program
    EXPECT_TRUE(panel.session().latest()->scene);
    panel.page(QStringLiteral("param"));
    EXPECT_FALSE(panel.session().latest()->scene);
}

} // namespace m350::test
