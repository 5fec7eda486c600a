// The spindle load signal, its conversion as the FANUC article does it, and the breakage monitor's
// sustained-anomaly rule, with hand-computed numbers.
#include "core/machine/SpindleLoadModel.h"
#include "core/tools/SpindleLoadMonitor.h"

#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;

TEST(SpindleLoadConversion, TheArticlesReadingOf301IsThreePointZeroOnePercent) {
    // 14300 x 691 / 32767 = 301.56: the ladder keeps 301, the host divides by 100
    EXPECT_EQ(machine::loadRegister(691, 143.0), 301);
    EXPECT_NEAR(machine::loadPercent(691, 143.0), 3.015625, 1e-6); // 691 / 32767 x 143
    EXPECT_DOUBLE_EQ(machine::loadPercent(32767, 143.0), 143.0);
    EXPECT_EQ(machine::loadRegister(32767, 143.0), 14300);
    EXPECT_EQ(machine::loadRegister(0, 143.0), 0);
}

TEST(SpindleLoadConversion, ModelAndSignalWithLambda143) {
    machine::SpindleLoadModel model; // idle 1.5, 0.3 per 1000 rpm, 2.5 per cm3/min
    // 6000 rpm, 600 mm/min, 2 mm deep, 10 mm wide: 1.5 + 1.8 + 2.5 x 12 = 33.3 %
    EXPECT_NEAR(model.percent(6000, 600, 2, 10), 33.3, 1e-12);
    EXPECT_DOUBLE_EQ(model.percent(0, 600, 2, 10), 0.0); // spindle stopped
    EXPECT_NEAR(model.percent(6000, 0, 2, 10), 3.3, 1e-12); // turning, not feeding
    // L = 33.3 / 143 x 32767 = 7630.3 -> 7630; register 14300 x 7630 / 32767 = 3329.8 -> 3329
    EXPECT_EQ(model.signal(33.3), 7630);
    EXPECT_EQ(machine::loadRegister(7630, 143.0), 3329);
    EXPECT_EQ(model.signal(500.0), 32767); // beyond full scale
    model.lambda = 200.0;
    EXPECT_EQ(model.signal(33.3), 5456); // 33.3 / 200 x 32767 = 5455.7
}

tools::LoadSample sample(double t, double percent, bool cutting = true) {
    tools::LoadSample s;
    s.time = t;
    s.tool = 1;
    s.percent = percent;
    s.cutting = cutting;
    return s;
}

tools::SpindleLoadMonitor monitorFor(double lower, double upper, int samples) {
    tools::LoadMonitorSettings settings;
    settings.samples = samples;
    settings.tools[1] = {lower, upper};
    tools::SpindleLoadMonitor monitor;
    monitor.setSettings(settings);
    return monitor;
}

TEST(SpindleLoadMonitor, AlarmsOnlyAfterTheGivenNumberOfSamplesInARow) {
    auto monitor = monitorFor(10.0, 60.0, 5);
    for (int i = 0; i < 4; ++i) {
        EXPECT_FALSE(monitor.add(sample(i * 0.1, 3.3)));
    }
    EXPECT_FALSE(monitor.add(sample(0.4, 33.3))); // back inside: the run starts again
    for (int i = 0; i < 4; ++i) {
        EXPECT_FALSE(monitor.add(sample(0.5 + i * 0.1, 3.3)));
    }
    auto alarm = monitor.add(sample(0.9, 3.3));
    ASSERT_TRUE(alarm);
    EXPECT_EQ(*alarm, "tool 1 spindle load out of its limits (10.00 - 60.00 %) for 5 samples since 0.50 s, "
                      "now 3.30 % (below): tool broken?");
}

TEST(SpindleLoadMonitor, ASpikeShorterThanTheRuleAndIdleOutsideACutAreNoAlarm) {
    auto monitor = monitorFor(10.0, 60.0, 5);
    for (int i = 0; i < 3; ++i) {
        EXPECT_FALSE(monitor.add(sample(i * 0.1, 78.3)));
    }
    for (int i = 0; i < 20; ++i) {
        EXPECT_FALSE(monitor.add(sample(1 + i * 0.1, 3.3, false))); // not cutting: no lower limit
    }
    for (int i = 0; i < 4; ++i) {
        EXPECT_FALSE(monitor.add(sample(3 + i * 0.1, 61.0, false)));
    }
    EXPECT_TRUE(monitor.add(sample(3.4, 61.0, false))); // the upper limit holds always
}

TEST(SpindleLoadMonitor, HistoryKeepsTheLast600Samples) {
    auto monitor = monitorFor(0.0, 0.0, 5);
    for (int i = 0; i < 1000; ++i) {
        monitor.add(sample(i * 0.1, 1.0));
    }
    EXPECT_EQ(monitor.taken(), 1000u);
    ASSERT_EQ(monitor.history().size(), tools::SpindleLoadMonitor::kHistory);
    EXPECT_DOUBLE_EQ(monitor.history().front().time, 40.0);
}

TEST(SpindleLoadLimits, ABadFileSaysWhereAndWhat) {
    std::string path = test::writeTempFile("[monitor]\nsamples = 5\n\n[tool.1]\nlower = 70\nupper = 60\n", ".toml");
    tools::LoadMonitorSettings settings;
    auto wrong = tools::readLoadMonitorSettings(path, settings);
    ASSERT_TRUE(wrong);
    EXPECT_EQ(wrong->line, 4) << wrong->message; // [tool.1]
    EXPECT_NE(wrong->message.english().find("need 0 <= lower < upper"), std::string::npos) << wrong->message;
    std::string good = test::writeTempFile("[monitor]\nsample_ms = 50\nsamples = 3\n[tool.2]\nlower = 8\nupper = 80\n", ".toml");
    ASSERT_FALSE(tools::readLoadMonitorSettings(good, settings));
    EXPECT_DOUBLE_EQ(settings.sampleSeconds, 0.05);
    EXPECT_EQ(settings.samples, 3);
    ASSERT_TRUE(settings.limitsFor(2));
    EXPECT_DOUBLE_EQ(settings.limitsFor(2)->upper, 80.0);
}

} // namespace
