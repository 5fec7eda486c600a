#pragma once

#include "core/common/Message.h"

#include <map>
#include <optional>
#include <string>

namespace m350::params {

// FANUC parameters (numbers 1000-99999) on FANUC-dialect machines: params.toml and --param keep
// them beside the shared 0-999 table. The simulator reads the ones listed in FanucParameters.cpp;
// others are kept as written, with a warning that nothing reads them.
inline constexpr int kFirstFanucParameter = 1000;
inline constexpr int kLastFanucParameter = 99999;
inline constexpr int kLoadMeterFullScale = 4127; // lambda: the load % the meter's full scale stands for
// Tool life management (the 0i seed's T function chapter): bit parameters are written as the byte's
// value (#0 = 1, #1 = 2, ... #7 = 128).
inline constexpr int kToolLifeSettings = 6800;     // #0 GS1, #1 GS2 (groups x tools), #2 LTM (0 count, 1 minutes)
inline constexpr int kToolLifeExtended = 6801;     // #6 EXT: G10 L3 P1 / P2 allowed
inline constexpr int kToolLifeIgnoreNumber = 6810; // T(ignore + n) selects group n
// Custom Macro B: codes that call programs (config/CallCodeParameters.h)
inline constexpr int kFirstGCodeMacroCall = 6050;      // 6050-6059: G code -> macro O9010-O9019
inline constexpr int kFirstMCodeSubprogramCall = 6071; // 6071-6079: M code -> subprogram O9001-O9009
inline constexpr int kFirstMCodeMacroCall = 6080;      // 6080-6089: M code -> macro O9020-O9029
inline constexpr int kFirstAddressCall = 6090;         // 6090-6091: address (ASCII) -> subprogram O9004, O9005

bool isFanucParameterNumber(int number);

// Why `value` cannot be parameter `number` (not finite, outside the simulated parameter's range).
std::optional<Message> refusedFanucParameter(int number, double value);

// A warning for a number the simulator does not read, to be shown beside the file or option.
std::optional<Message> unreadFanucParameter(int number);

// The parameter's value, or the FANUC default when the machine does not set it.
double fanucParameter(const std::map<int, double>& values, int number);

} // namespace m350::params
