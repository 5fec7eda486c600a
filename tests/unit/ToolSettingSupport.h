#pragma once

// Shared by the tool-setting tests (O502, O505, O506/O507 in slib-probe.nc): the simulated world's
// trip heights and the macro alarms the tool-setting macros raise.
#include "RunProgram.h"

#include <gtest/gtest.h>

#include <string>

namespace m350::test {

// The simulated fixed setter trips where the tip meets its top: spindle-nose Z = top + tool length.
inline double tripHeight(const config::MachineConfig& cfg, int tool) {
    return cfg.setterTop + cfg.toolLengths[static_cast<std::size_t>(tool - 1)];
}

// The manual's setter (对刀参数设置): X Y Z 555.269 / 66.381 / -53.677, 3 passes from 250 mm/min,
// thickness 10, back 50 mm after setting.
inline void useManualSetter(config::MachineConfig& cfg) {
    cfg.parameters.set(135, 555.269);
    cfg.parameters.set(136, 66.381);
    cfg.parameters.set(137, -53.677);
    cfg.parameters.set(129, 10);
    cfg.parameters.set(131, 3);
    cfg.parameters.set(132, 250);
    cfg.parameters.set(140, 50);
}

// The run stopped with `#3000 = number(text)`.
inline void expectMacroAlarm(const ProgramRun& run, int number, const std::string& text) {
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm) << run.alarmText();
    ASSERT_TRUE(run.report.alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::MacroAlarm);
    EXPECT_EQ(run.report.alarm->message, "macro alarm " + std::to_string(3000 + number) + ": " + text);
    EXPECT_EQ(run.report.alarm->file, "slib-probe.nc");
}

} // namespace m350::test
