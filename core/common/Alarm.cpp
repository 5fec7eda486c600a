#include "core/common/Alarm.h"

namespace m350 {

std::string_view alarmKey(AlarmCode code) {
    switch (code) {
    case AlarmCode::DivisionByZero: return "division_by_zero";
    case AlarmCode::InvalidArgument: return "invalid_argument";
    case AlarmCode::UndefinedVariable: return "undefined_variable";
    case AlarmCode::ReadOnlyVariable: return "read_only_variable";
    case AlarmCode::GotoMissingLabel: return "goto_missing_label";
    case AlarmCode::EndWithoutDo: return "end_without_do";
    case AlarmCode::WhileWithoutEnd: return "while_without_end";
    case AlarmCode::CallNestingTooDeep: return "call_nesting_too_deep";
    case AlarmCode::UnknownProgram: return "unknown_program";
    case AlarmCode::MissingAddress: return "missing_address";
    case AlarmCode::InvalidWord: return "invalid_word";
    case AlarmCode::MacroAlarm: return "macro_alarm";
    case AlarmCode::SuspectLine: return "suspect_line";
    case AlarmCode::SimulatedTimeLimit: return "simulated_time_limit";
    case AlarmCode::NotHomed: return "not_homed";
    case AlarmCode::SoftLimit: return "soft_limit";
    case AlarmCode::SkipNotTriggered: return "skip_not_triggered";
    case AlarmCode::SensorTimeout: return "sensor_timeout";
    case AlarmCode::Crash: return "crash";
    case AlarmCode::DeviceError: return "device_error";
    case AlarmCode::ToolLifeExpired: return "tool_life_expired";
    case AlarmCode::SpindleLoad: return "spindle_load";
    case AlarmCode::OperatorReset: return "reset";
    case AlarmCode::EmergencyStop: return "emergency_stop";
    case AlarmCode::RightsLimited: return "rights_limited";
    }
    return "unknown";
}

} // namespace m350
