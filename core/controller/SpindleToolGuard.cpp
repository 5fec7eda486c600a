#include "core/controller/SpindleToolGuard.h"

#include "core/common/Numeric.h"
#include "core/gcode/Dialect.h"
#include "core/macro/Executor.h"
#include "core/macro/MacroError.h"
#include "core/params/ParameterNumbers.h"
#include "core/params/ParameterTable.h"
#include "core/tools/ToolData.h"

#include <algorithm>
#include <string>
#include <utility>

namespace m350::controller {

SpindleToolGuard::SpindleToolGuard(Context context) : context_(std::move(context)) {}

bool SpindleToolGuard::changingTool() const { return context_.executor && context_.executor->changingTool(); }

// After a stop in a change, the next change (an M350's T, a FANUC's M06) would start from a tool
// the controller only believes is in the spindle: refused at its word until the operator says.
void SpindleToolGuard::refuseChangeInDoubt(const macro::EvaluatedBlock& block) const {
    if (!context_.magazine.device() || changingTool() || block.gCodes.has(65) || block.gCodes.has(66)) {
        return;
    }
    const bool m350 = context_.dialect.id == gcode::DialectId::M350;
    const auto word = std::find_if(block.words.begin(), block.words.end(), [m350](const macro::WordValue& w) {
        return m350 ? w.letter == 'T' : w.letter == 'M' && w.value == 6.0;
    });
    if (word != block.words.end()) {
        throw macro::MacroError::of(AlarmCode::InvalidArgument, doubt_.refusal(), word->column);
    }
}

// The T code goes to the PMC as the block starts (FANUC's T strobe), before its motion and before
// M06 calls the change program: a T the magazine cannot serve is refused there, at the T word. A T
// that is a macro's argument (G65/G66 P.. T..) selects nothing.
void SpindleToolGuard::refuseToolWord(const macro::EvaluatedBlock& block) const {
    if (block.mCodes.has(61)) {
        const auto m61 = std::find_if(block.words.begin(), block.words.end(),
                                      [](const macro::WordValue& w) { return w.letter == 'M' && w.value == 61.0; });
        throw macro::MacroError::of(AlarmCode::InvalidWord, message("m61_with_magazine"), m61->column);
    }
    if (block.gCodes.has(65) || block.gCodes.has(66) || block.otherCodes) {
        return;
    }
    const macro::WordValue& t = block.words[block.firstOf['T' - 'A']];
    if (auto why = context_.magazine.refusedTool(roundToInt(t.value))) {
        throw macro::MacroError::of(AlarmCode::InvalidArgument, *why, t.column);
    }
}

std::optional<Alarm> SpindleToolGuard::stoppedInChange(int pmcSpindleTool) {
    const bool m350 = context_.dialect.id == gcode::DialectId::M350;
    const macro::Value target = m350 ? context_.variable(1504) : macro::Value::of(lastToolWord_);
    const int recorded = m350 ? saturatingInt(context_.parameters.get(param::kCurrentTool)) : pmcSpindleTool;
    if (!doubt_.stoppedInChange(target.vacant ? 0 : roundToInt(target.number), recorded)) {
        return std::nullopt;
    }
    return doubt_.notice();
}

// One never set leaves work Z wrong by the whole tool length. Without the fixed setter an offset
// of 0 is how the manual's single-tool 清零 works.
std::optional<Alarm> SpindleToolGuard::toolTurns(int tool, const TraceSource& where) {
    lengthLookedAt_ = tool;
    const params::ParameterTable& p = context_.parameters;
    if (context_.dialect.id != gcode::DialectId::M350 || tool == 0 || p.get(param::kFixedSetterValid) == 0.0 ||
        !lengthWarned_.insert(tool).second) {
        return std::nullopt;
    }
    const std::optional<int> parameter = tools::m350ZParameter(tool, p);
    if (!parameter || p.get(*parameter) != 0.0) {
        return std::nullopt;
    }
    const std::string t = std::to_string(tool);
    const std::string n = std::to_string(*parameter);
    Alarm warning;
    warning.code = AlarmCode::InvalidArgument;
    warning.message = "T" + t + " turns with no Z offset (param " + n + " = 0): set the tool before it cuts";
    warning.file = where.file;
    warning.line = where.line;
    warning.messageId = "tool_length_unset";
    warning.messageArguments = {t, n};
    return warning;
}

} // namespace m350::controller
