// The #1505 operator dialog: with a person at the panel the run holds after the block until the
// dialog is answered, and the answer decides the macro's path; without one Enter comes at once.
#include "RunProgram.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

using namespace m350;
using namespace m350::test;
using RunState = controller::Controller::RunState;

// Enter goes to X10, Esc to X20; the dialog's block is followed by a move so a run that does not
// wait shows it in the position.
const std::string kAsk = lines({
    "#1505 = 1(Change to T2?)",
    "IF #1505 == 1 GOTO1",
    "G00 X20",
    "GOTO2",
    "N1 G00 X10",
    "N2 #100 = 5",
    "M30",
});

std::unique_ptr<controller::Controller> started(const std::string& program, bool operatorPresent) {
    controller::RunSettings settings;
    settings.operatorPresent = operatorPresent;
    auto c = std::make_unique<controller::Controller>(m350Machine(), settings);
    EXPECT_TRUE(c->loadFile(writeTempFile(program)));
    EXPECT_TRUE(c->start());
    return c;
}

bool said(const controller::RunReport& r, const std::string& text) {
    return std::any_of(r.messages.begin(), r.messages.end(),
                       [&](const std::string& m) { return m.find(text) != std::string::npos; });
}

TEST(OperatorDialog, TheRunHoldsUntilEnterAndTakesTheEnterPath) {
    auto c = started(kAsk, true);
    EXPECT_EQ(c->advance(60.0), RunState::Running);
    ASSERT_TRUE(c->operatorPanel().pendingDialog());
    EXPECT_EQ(c->operatorPanel().pendingDialog()->text, "Change to T2?");
    EXPECT_EQ(c->operatorPanel().pendingDialog()->kind, 1);
    EXPECT_EQ(c->panelStatus().dialog, std::optional<std::string>("Change to T2?"));
    EXPECT_EQ(c->status().report().machine(0), 0.0); // nothing after the dialog's block ran
    EXPECT_EQ(c->variable(100).number, 0.0);
    c->operatorPanel().answerDialog(true);
    EXPECT_FALSE(c->operatorPanel().pendingDialog());
    EXPECT_FALSE(c->panelStatus().dialog);
    EXPECT_EQ(c->advance(60.0), RunState::Finished);
    EXPECT_NEAR(c->status().report().machine(0), 10.0, 1e-9);
    EXPECT_EQ(c->variable(100).number, 5.0);
    EXPECT_TRUE(said(c->status().report(), "Change to T2? [dialog answered: Enter]"));
}

TEST(OperatorDialog, EscTakesTheOtherPath) {
    auto c = started(kAsk, true);
    c->advance(5.0);
    ASSERT_TRUE(c->operatorPanel().pendingDialog());
    c->operatorPanel().answerDialog(false);
    EXPECT_EQ(c->advance(60.0), RunState::Finished);
    EXPECT_NEAR(c->status().report().machine(0), 20.0, 1e-9);
    EXPECT_EQ(c->variable(1505).number, 0.0);
    // the machine's clock ran while the operator read the dialog
    EXPECT_GE(c->status().report().simTime, 5.0);
}

TEST(OperatorDialog, MessageOnlyDoesNotHold) {
    auto c = started(lines({"#1505 = -5000(Spindle warming up)", "G00 X7", "M30"}), true);
    EXPECT_EQ(c->advance(60.0), RunState::Finished);
    EXPECT_FALSE(c->operatorPanel().pendingDialog());
    EXPECT_NEAR(c->status().report().machine(0), 7.0, 1e-9);
    EXPECT_EQ(c->panelStatus().message, "Spindle warming up");
}

TEST(OperatorDialog, WithoutAnOperatorEnterComesAtOnce) {
    auto c = started(kAsk, false);
    EXPECT_EQ(c->advance(60.0), RunState::Finished);
    EXPECT_FALSE(c->operatorPanel().pendingDialog());
    EXPECT_NEAR(c->status().report().machine(0), 10.0, 1e-9);
    EXPECT_TRUE(said(c->status().report(), "Change to T2? [dialog answered: Enter]"));
}

TEST(OperatorDialog, RunAnswersEnterEvenWithAnOperatorSet) {
    controller::RunSettings settings;
    settings.operatorPresent = true;
    ProgramRun run = runM350(kAsk, settings);
    EXPECT_RUN_OK(run);
    EXPECT_NEAR(run.report.machine(0), 10.0, 1e-9);
    EXPECT_TRUE(said(run.report, "[dialog answered: Enter]"));
}

TEST(OperatorDialog, ResetDropsThePendingDialog) {
    auto c = started(kAsk, true);
    c->advance(1.0);
    ASSERT_TRUE(c->operatorPanel().pendingDialog());
    c->reset();
    EXPECT_FALSE(c->operatorPanel().pendingDialog());
    EXPECT_EQ(c->runState(), RunState::Idle);
}

TEST(PanelControls, ExternStartKeyIsPressedForAMoment) {
    auto cfg = m350Machine();
    cfg.parameters.set(599, 5);
    cfg.parameters.set(600, 1);
    cfg.parameters.set(601, 1);
    // waits for IN05 to come and go, as O20001 does
    controller::RunSettings settings;
    settings.operatorPresent = true;
    auto c = std::make_unique<controller::Controller>(std::move(cfg), settings);
    ASSERT_TRUE(c->loadFile(writeTempFile(lines({"WHILE [#1524 NE 1] DO1", "G04 P10", "END1",
                                                 "WHILE [#1524 EQ 1] DO2", "G04 P10", "END2", "#100 = 1",
                                                 "M30"}))));
    ASSERT_TRUE(c->start());
    EXPECT_EQ(c->advance(30.0), RunState::Running); // no sensor_timeout: the key is the operator's
    c->operatorPanel().pressExternStart();
    EXPECT_EQ(c->advance(1.0), RunState::Finished);
    EXPECT_EQ(c->variable(100).number, 1.0);
}

TEST(PanelControls, ParametersReadAndWrittenByNumber) {
    controller::Controller c(m350Machine(), {});
    EXPECT_TRUE(c.setParameter(135, 412.5));
    EXPECT_EQ(c.parameter(135), 412.5);
    EXPECT_EQ(c.variable(635).number, 412.5);
    EXPECT_FALSE(c.setParameter(1000, 1.0));
    EXPECT_FALSE(c.setParameter(-1, 1.0));
    EXPECT_FALSE(c.setParameter(136, std::nan("")));
    EXPECT_FALSE(c.setParameter(136, INFINITY));
    EXPECT_EQ(c.parameter(136), 0.0);
}

TEST(PanelControls, ATaughtSetterPositionMovesWhereTheSetterTrips) {
    // the fixed setter on IN12 at X 50 Y 0: G31 trips over it only after param 135 says it is there
    auto cfg = m350Machine();
    cfg.parameters.set(575, 12);
    cfg.parameters.set(576, 1);
    cfg.parameters.set(577, 1);
    cfg.setterTop = -100.0;
    controller::Controller c(std::move(cfg), {});
    ASSERT_TRUE(c.setParameter(135, 50.0));
    ASSERT_TRUE(c.loadMdi({"G53 X50 Y0", "G91 G31 Z-200 F500 P12 L1", "G90"}));
    controller::RunReport r = c.run();
    EXPECT_EQ(r.status, controller::RunStatus::Ok) << (r.alarm ? r.alarm->message : "");
    EXPECT_NEAR(r.machine(2), -100.0, 1e-9);
}

} // namespace
