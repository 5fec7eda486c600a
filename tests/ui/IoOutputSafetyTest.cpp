// The IO page's output switches: each goes into the 系统日志, and releasing the drawbar with a tool
// in the spindle is asked first.
#include "tests/ui/PanelHarness.h"

#include "core/params/ParameterNumbers.h"
#include "ui/pages/IoPage.h"
#include "ui/panel/PromptBox.h"

namespace m350::test {

namespace {

int output(PanelHarness& panel, int pin) { return panel.session().latest()->status.outputs[static_cast<std::size_t>(pin - 1)]; }

bool logged(PanelHarness& panel, const std::string& event, const std::string& detail) {
    for (const files::LogEntry& entry : *panel.session().latest()->log) {
        if (entry.event == event && entry.detail == detail) {
            return true;
        }
    }
    return false;
}

ui::IoPage* ioPage(PanelHarness& panel, int parameter) {
    panel.key("IO");
    auto* io = panel.page<ui::IoPage>();
    EXPECT_NE(io, nullptr);
    panel.advance(0.05);
    EXPECT_TRUE(io && io->selectFunction(parameter)) << parameter;
    return io;
}

} // namespace

TEST(IoOutputSafety, AnOutputSwitchedOnTheIoPageIsLogged) {
    ui::MachineSession::Options options;
    options.tool = 0;
    PanelHarness panel(options); // m350-linear16: the drawbar on OUT01, the spindle empty
    ASSERT_EQ(panel.session().latest()->status.tool, 0);
    ioPage(panel, param::kDrawbarOutput);
    panel.softkey(1); // 输出开
    EXPECT_FALSE(panel.window().prompt()->active()) << "no tool, no question";
    EXPECT_EQ(output(panel, 1), 1);
    EXPECT_TRUE(logged(panel, "output", "OUT01 = 1"));
    panel.softkey(2); // 输出关
    EXPECT_EQ(output(panel, 1), 0);
    EXPECT_TRUE(logged(panel, "output", "OUT01 = 0"));
}

TEST(IoOutputSafety, ReleasingTheDrawbarWithAToolAsksFirst) {
    ui::MachineSession::Options options;
    options.tool = 3;
    PanelHarness panel(options);
    ASSERT_EQ(panel.session().latest()->status.tool, 3);
    ioPage(panel, param::kDrawbarOutput);
    panel.softkey(1);
    ASSERT_TRUE(panel.window().prompt()->active());
    EXPECT_TRUE(panel.window().state()["prompt"].toString().contains(QStringLiteral("T3")));
    EXPECT_EQ(output(panel, 1), 0) << "nothing switched before the answer";
    panel.key("ESC");
    EXPECT_FALSE(panel.window().prompt()->active());
    EXPECT_EQ(output(panel, 1), 0) << "Esc keeps the tool clamped";
    EXPECT_FALSE(logged(panel, "output", "OUT01 = 1"));

    panel.softkey(1);
    ASSERT_TRUE(panel.window().prompt()->active());
    panel.key("ENTER");
    // Enter releases: the tool falls out (the simulated world's alarm says so)
    EXPECT_EQ(panel.session().latest()->status.tool, 0);
    EXPECT_TRUE(panel.window().state()["alarm_text"].toString().contains(QStringLiteral("T3")));
    EXPECT_TRUE(logged(panel, "output", "OUT01 = 1"));
}

} // namespace m350::test
