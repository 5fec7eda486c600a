#include "core/config/CallCodeParameters.h"

#include "core/config/MachineConfig.h"
#include "core/params/FanucParameters.h"

#include <cmath>
#include <cstdio>
#include <string_view>

namespace m350::config {

namespace {

using macro::CallKind;
using macro::CodeCall;

struct Range {
    int first;
    int count;
    char letter;          // 'G', 'M', or 0 for an address
    std::int32_t program; // called by the first parameter of the range
    CallKind kind;
};

constexpr Range kRanges[] = {
    {params::kFirstGCodeMacroCall, 10, 'G', 9010, CallKind::Macro},
    {params::kFirstMCodeSubprogramCall, 9, 'M', 9001, CallKind::Subprogram},
    {params::kFirstMCodeMacroCall, 10, 'M', 9020, CallKind::Macro},
    {params::kFirstAddressCall, 2, 0, 9004, CallKind::Subprogram},
};

constexpr int kFirstAddressVariable = 146; // O9004 receives the value in #146, O9005 in #147

// The addresses the Power Mate i macro executor manual lists for 6090/6091, less M: an M word
// is a code, and making every one call O9004 would take M30 and M99 with it.
constexpr std::string_view kCallingAddresses = "ABDFHIJKQRST";

// Codes the executor and the interpreter must keep: the calls themselves and the program end.
bool reservedCode(char letter, int code) {
    return (letter == 'G' && code == 65) || (letter == 'M' && (code == 30 || code == 98 || code == 99));
}

std::string shortNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", value);
    return text;
}

} // namespace

std::optional<CallParameterError> addCallParameters(macro::CallCodes& table,
                                                    const std::map<int, double>& values,
                                                    const std::map<int, std::string>& origins) {
    for (const Range& range : kRanges) {
        for (int k = 0; k < range.count; ++k) {
            const int number = range.first + k;
            auto value = values.find(number);
            if (value == values.end() || value->second == 0.0) {
                continue;
            }
            auto place = origins.find(number);
            const std::string setting = bilingual("parameter " + std::to_string(number) + " = " + shortNumber(value->second),
                                                  "参数" + std::to_string(number) + " = " + shortNumber(value->second));
            // said inside another parameter's clash message, in that message's language
            const std::string where = place != origins.end() ? " (" + place->second + ")" : std::string();
            const std::string origin = bilingual(argumentIn(setting, MessageLanguage::English) + where,
                                                 argumentIn(setting, MessageLanguage::Chinese) + where);
            const double v = value->second;
            if (v != std::floor(v)) {
                return CallParameterError{message("call_param_whole", {setting}), number};
            }
            const int code = static_cast<int>(v);
            CodeCall call{range.program + k, range.kind, 0, origin};
            if (range.letter == 0) {
                const char letter = static_cast<char>(code);
                if (code < 'A' || code > 'Z' || kCallingAddresses.find(letter) == std::string_view::npos) {
                    return CallParameterError{message("call_param_address", {setting, std::to_string(call.program)}),
                                              number};
                }
                call.valueVariable = kFirstAddressVariable + k;
                if (auto clash = table.addAddress(letter, call)) {
                    return CallParameterError{message("call_param_address_clash",
                                                      {setting, std::string(1, letter), std::to_string(call.program),
                                                       clash->origin, std::to_string(clash->program)}),
                                              number};
                }
                continue;
            }
            const std::string name = std::string(1, range.letter) + std::to_string(code);
            if (reservedCode(range.letter, code)) {
                return CallParameterError{message("call_param_reserved", {setting, name}), number};
            }
            if (auto clash = table.add(range.letter, code, call)) {
                return CallParameterError{message("call_param_clash", {setting, name, std::to_string(call.program),
                                                                       clash->origin, std::to_string(clash->program)}),
                                          number};
            }
        }
    }
    return std::nullopt;
}

std::optional<CallParameterError> rebuildCallCodes(MachineConfig& config) {
    macro::CallCodes table = config.codeCalls;
    if (config.dialect->id == gcode::DialectId::Fanuc) {
        if (auto refused = addCallParameters(table, config.fanucParameters, config.fanucParameterOrigins)) {
            return refused;
        }
    }
    config.callCodes = std::move(table);
    return std::nullopt;
}

gcode::Dialect parsingDialect(const MachineConfig& config) {
    gcode::Dialect dialect = *config.dialect;
    for (const auto& [code, call] : config.callCodes.codes()) {
        if (call.kind == macro::CallKind::Macro) {
            dialect.argumentCodes.push_back(code);
        }
    }
    return dialect;
}

} // namespace m350::config
