#pragma once

#include "core/common/Message.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace m350 {

// Every alarm the simulator can raise. Keys are stable, untranslated identifiers (the CLI prints
// them, the UI translates them); the message says what happened in the operator's terms.
enum class AlarmCode : std::uint8_t {
    DivisionByZero,
    InvalidArgument,      // SQRT of a negative number, ACOS of 2 ...
    UndefinedVariable,
    ReadOnlyVariable,
    GotoMissingLabel,
    EndWithoutDo,
    WhileWithoutEnd,
    CallNestingTooDeep,
    UnknownProgram,
    MissingAddress,       // M98 without P ...
    InvalidWord,          // a G or M code the machine does not know, a bad value
    MacroAlarm,           // FANUC #3000
    SuspectLine,          // a line `check` flags as never meant (X[#1330+#1300-1])
    SimulatedTimeLimit,   // runaway loop
    NotHomed,
    SoftLimit,
    SkipNotTriggered,     // G31 ended its move without the signal
    SensorTimeout,        // a macro waited longer than the sensor watchdog for an input
    Crash,                // the magazine hardware was hit, a tool dropped: what the real machine would suffer
    DeviceError,          // DPRNT without POPEN, a Modbus slave that does not answer or refuses a register
    ToolLifeExpired,      // every tool of a tool life group has reached its life
    SpindleLoad,          // the breakage monitor: the spindle load stayed out of the tool's limits
    OperatorReset,
    EmergencyStop,
    RightsLimited,        // a program typed at the panel wrote a parameter above the user level (issue 26)
};

std::string_view alarmKey(AlarmCode code);

// A raised alarm: what and where. Alarms are values; they are stored and reported, never thrown
// across layers.
struct Alarm {
    AlarmCode code = AlarmCode::InvalidWord;
    std::string message;
    std::string file;
    std::uint32_t line = 0;
    std::uint32_t column = 0;
    // When the alarm is in a library (slib-g.nc's O20000 for `T2.5`), the line of the user's
    // program or MDI that called it; callerLine 0 when the alarm is on the user's own line.
    std::string callerFile{};
    std::uint32_t callerLine = 0;
    // The message's words by a stable id, for the panel to say in its language ("modbus_no_answer"
    // with its arguments in order: ui/i18n/AlarmText); empty for the alarms `message` alone says.
    std::string messageId{};
    std::vector<std::string> messageArguments{};

    // An alarm said by a message of the table: its English is `message`, its id and arguments
    // let the panel and `m350-sim --lang` say it in theirs.
    static Alarm of(AlarmCode code, const Message& words, std::string file = {}, std::uint32_t line = 0,
                    std::uint32_t column = 0) {
        return Alarm{code, words.english(), std::move(file), line, column, {}, 0, words.id, words.arguments};
    }
};

} // namespace m350
