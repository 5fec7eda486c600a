#pragma once

#include "core/common/Message.h"
#include "core/gcode/Dialect.h"
#include "core/macro/CallCodes.h"

#include <cstddef>
#include <map>
#include <optional>
#include <string>

namespace m350::config {

// The FANUC parameters that make codes call programs, as the 0i configures them:
//   6050-6059  the G code that calls the macro O9010-O9019 (like G65: arguments #1-#26)
//   6071-6079  the M code that calls the subprogram O9001-O9009 (like M98: no arguments)
//   6080-6089  the M code that calls the macro O9020-O9029 (like G65)
//   6090-6091  the ASCII code of the address that calls the subprogram O9004 / O9005, its value
//              in #146 / #147
// `values` are the machine's FANUC parameters, `origins` where each was set ("params.toml:4:8",
// "--param 6050=100"; a number missing there is named "parameter N"). The entries join `table`,
// which holds machine.toml's [codes] already. Refused: a value that is no code (a fraction, G65,
// M98, M99, M30, a letter that cannot call), and two settings for one code (both named).
struct CallParameterError {
    Message message;
    int parameter = 0; // the setting refused
};
std::optional<CallParameterError> addCallParameters(macro::CallCodes& table,
                                                    const std::map<int, double>& values,
                                                    const std::map<int, std::string>& origins);

struct MachineConfig;
// config.callCodes made again from config.codeCalls ([codes]) and, on a FANUC machine, its call
// parameters: at load and after --param changed one. On a refusal callCodes stays as it was.
std::optional<CallParameterError> rebuildCallCodes(MachineConfig& config);

// The machine's dialect as its programs are parsed: the codes that call macros pass arguments as
// G65 does, so in their blocks `X1.E2.` is X and the argument E (gcode::Dialect::argumentCodes).
gcode::Dialect parsingDialect(const MachineConfig& config);

} // namespace m350::config
