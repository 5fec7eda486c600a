// 试切 from the panel: with MPG RUN on, an MDI line advances only while the wheel turns.
#include "tests/ui/PanelHarness.h"

#include "ui/pages/MonitorPage.h"
#include "ui/panel/StatusLine.h"

namespace m350::test {

TEST(HandwheelGuide, TheProgramAdvancesOnlyWhileTheWheelTurns) {
    PanelHarness panel;
    panel.key("MPG_RUN");
    EXPECT_EQ(panel.window().statusLine()->modeText(), QStringLiteral("试切"));
    panel.key("MDI");
    panel.type("G91 G1 X200 F1200");
    panel.key("ENTER");
    panel.softkey(1);
    auto x = [&panel] { return panel.session().latest()->status.machine(0); };
    const double start = x();
    panel.advance(1.0);
    EXPECT_NEAR(x(), start, 1e-6) << "no wheel, no motion";

    panel.turnWheel(0, 10, 2, 1.0); // two detents a frame at x10
    const double turned = x();
    EXPECT_GT(turned, start + 0.1) << "the wheel drives the program";
    EXPECT_EQ(panel.window().statusLine()->stateText(), QStringLiteral("顺切"));

    panel.advance(3.0); // the wheel stopped: the override decays, the motion comes to rest
    const double rest = x();
    panel.advance(2.0);
    EXPECT_NEAR(x(), rest, 1e-6) << "at rest once the wheel has stopped";
    EXPECT_LT(rest, start + 200.0) << "the program did not run to its end by itself";
}

} // namespace m350::test
