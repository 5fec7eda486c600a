// The operator's keys wired to inputs (params 581-605) through the controller: a press of an
// external key, START or PAUSE is queued once for the panel; the extern E-stop stops the machine
// while its input is active, also after RESET.
#include "RunProgram.h"

#include "core/controller/OperatorInputs.h"
#include "core/machine/InputFault.h"
#include "core/machine/SimulatedMachine.h"
#include "core/params/ParameterTable.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using controller::Controller;
using Kind = controller::OperatorKey::Kind;
using machine::InputFault;

constexpr int kPin = 21;

void wire(config::MachineConfig& cfg, int parameter, int pin) {
    cfg.parameters.set(parameter, pin);
    cfg.parameters.set(parameter + 1, 1); // enabled
    cfg.parameters.set(parameter + 2, 1); // active at 1
}

void press(Controller& c, int pin) {
    c.setInputFault(pin, InputFault::stuck(1));
    c.advance(0.02);
}

void release(Controller& c, int pin) {
    c.setInputFault(pin, InputFault::stuck(0));
    c.advance(0.02);
}

TEST(OperatorInputs, AnExternalKeyIsOnePressWhileHeld) {
    config::MachineConfig cfg = test::m350Machine();
    wire(cfg, 587, kPin); // external key 3
    Controller c(std::move(cfg), {});
    c.advance(0.02);
    EXPECT_TRUE(c.operatorPanel().takeOperatorKeys().empty());
    press(c, kPin);
    c.advance(0.5);
    EXPECT_EQ(c.operatorPanel().takeOperatorKeys(), (std::vector<controller::OperatorKey>{{Kind::ExternKey, 3}}));
    c.advance(0.5); // still held
    EXPECT_TRUE(c.operatorPanel().takeOperatorKeys().empty());
    release(c, kPin);
    press(c, kPin);
    EXPECT_EQ(c.operatorPanel().takeOperatorKeys(), (std::vector<controller::OperatorKey>{{Kind::ExternKey, 3}}));
}

TEST(OperatorInputs, AKeyActiveWhenItIsWiredIsNoPressUntilPressedAgain) {
    config::MachineConfig cfg = test::m350Machine();
    wire(cfg, 581, kPin);
    cfg.parameters.set(583, 0); // active at 0: the idle input reads 0 from power-on
    Controller c(std::move(cfg), {});
    c.advance(0.02);
    EXPECT_TRUE(c.operatorPanel().takeOperatorKeys().empty());
    ASSERT_TRUE(c.setParameter(581, kPin + 1)); // moved to another idle input
    c.advance(0.02);
    EXPECT_TRUE(c.operatorPanel().takeOperatorKeys().empty());
    c.setInputFault(kPin + 1, InputFault::stuck(1));
    c.advance(0.02);
    c.setInputFault(kPin + 1, InputFault::stuck(0));
    c.advance(0.02);
    EXPECT_EQ(c.operatorPanel().takeOperatorKeys(), (std::vector<controller::OperatorKey>{{Kind::ExternKey, 1}}));
}

TEST(OperatorInputs, AnUnwiredOrDisabledKeyIsNoPress) {
    config::MachineConfig cfg = test::m350Machine();
    wire(cfg, 581, kPin);
    cfg.parameters.set(582, 0); // key 1 disabled
    Controller c(std::move(cfg), {});
    press(c, kPin);
    press(c, kPin + 1);
    EXPECT_TRUE(c.operatorPanel().takeOperatorKeys().empty());
}

TEST(OperatorInputs, StartIsNoKeyPressWhileAProgramRunsButPauseIs) {
    config::MachineConfig cfg = test::m350Machine();
    wire(cfg, 599, kPin);     // extern START
    wire(cfg, 602, kPin + 1); // extern PAUSE
    Controller c(std::move(cfg), {});
    ASSERT_TRUE(c.loadMdi({"G91 G1 X100 F600"}));
    ASSERT_TRUE(c.start());
    c.advance(0.5);
    press(c, kPin);
    press(c, kPin + 1);
    EXPECT_EQ(c.operatorPanel().takeOperatorKeys(), (std::vector<controller::OperatorKey>{{Kind::Pause, 0}}));
    EXPECT_EQ(c.runState(), Controller::RunState::Running); // the panel holds, not the core
    release(c, kPin);
    c.hold();
    press(c, kPin);
    EXPECT_EQ(c.operatorPanel().takeOperatorKeys(), (std::vector<controller::OperatorKey>{{Kind::Start, 0}}));
}

TEST(OperatorInputs, TheQueueKeepsTheNewestPresses) {
    config::MachineConfig cfg = test::m350Machine();
    wire(cfg, 581, kPin);
    Controller c(std::move(cfg), {});
    for (std::size_t i = 0; i < controller::OperatorPanel::kOperatorKeyQueue + 5; ++i) {
        press(c, kPin);
        release(c, kPin);
    }
    EXPECT_EQ(c.operatorPanel().takeOperatorKeys().size(), controller::OperatorPanel::kOperatorKeyQueue);
}

TEST(OperatorInputs, TheExternEStopStopsMotionAndHoldsThroughReset) {
    config::MachineConfig cfg = test::m350Machine();
    wire(cfg, 605, kPin);
    cfg.parameters.set(715, 3); // spindle forward on OUT03
    cfg.parameters.set(716, 1);
    cfg.parameters.set(717, 1);
    Controller c(std::move(cfg), {});
    ASSERT_TRUE(c.loadMdi({"M3 S1000", "G91 G1 X100 F600"}));
    ASSERT_TRUE(c.start());
    c.advance(1.0);
    ASSERT_EQ(c.runState(), Controller::RunState::Running);
    const double x = c.panelStatus().machine(0);
    press(c, kPin);
    EXPECT_EQ(c.runState(), Controller::RunState::EStop);
    ASSERT_TRUE(c.status().report().alarm);
    EXPECT_NE(c.status().report().alarm->message.find("extern E-stop (IN21)"), std::string::npos) << c.status().report().alarm->message;
    EXPECT_EQ(c.status().report().outputs[2], 0);
    c.advance(1.0);
    EXPECT_NEAR(c.panelStatus().machine(0), x, 0.5); // stopped where the key was pressed
    c.reset();
    c.advance(0.02);
    EXPECT_EQ(c.runState(), Controller::RunState::EStop) << "RESET while the E-stop is held";
    release(c, kPin);
    c.reset();
    c.advance(0.02);
    EXPECT_EQ(c.runState(), Controller::RunState::Idle);
    EXPECT_TRUE(c.operatorPanel().takeOperatorKeys().empty());
}

} // namespace

namespace {

using namespace m350;

// controller::OperatorInputs on its own: the parameters and the machine's inputs are all it reads.
TEST(OperatorInputs, ReadsTheWiredKeysWithoutAController) {
    params::ParameterTable parameters;
    machine::SimulatedMachine machine;
    parameters.set(587, kPin); // external key 3
    parameters.set(588, 1);
    parameters.set(589, 1);
    parameters.set(605, kPin + 1); // extern E-stop
    parameters.set(606, 1);
    parameters.set(607, 1);
    controller::OperatorInputs inputs;
    EXPECT_FALSE(inputs.watch(parameters, machine, false));
    machine.setInputFault(kPin, machine::InputFault::stuck(1));
    EXPECT_FALSE(inputs.watch(parameters, machine, false));
    EXPECT_EQ(inputs.take(), (std::vector<controller::OperatorKey>{{controller::OperatorKey::Kind::ExternKey, 3}}));
    machine.setInputFault(kPin + 1, machine::InputFault::stuck(1));
    std::optional<std::string> eStop = inputs.watch(parameters, machine, false);
    ASSERT_TRUE(eStop);
    EXPECT_EQ(*eStop, params::inputName(kPin + 1));
    EXPECT_TRUE(inputs.take().empty());
}

} // namespace
