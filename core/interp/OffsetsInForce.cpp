#include "core/interp/OffsetsInForce.h"

#include "core/common/Numeric.h"
#include "core/gcode/Dialect.h"
#include "core/params/ParameterNumbers.h"
#include "core/params/ParameterTable.h"
#include "core/tools/ToolData.h"

#include <optional>

namespace m350::interp {

OffsetsInForce::OffsetsInForce(const gcode::Dialect& dialect, const params::ParameterTable& parameters,
                               const WorkOffsets& offsets, const ModalState& state)
    : dialect_(dialect), parameters_(parameters), offsets_(offsets), state_(state) {}

int OffsetsInForce::currentTool() const {
    return dialect_.id == gcode::DialectId::M350 ? saturatingInt(parameters_.get(param::kCurrentTool))
                                                  : state_.selectedTool;
}

double OffsetsInForce::toolZOffset() const {
    if (dialect_.id != gcode::DialectId::M350) {
        return 0.0;
    }
    std::optional<int> parameter = tools::m350ZParameter(currentTool(), parameters_);
    return parameter ? parameters_.get(*parameter) : 0.0;
}

double OffsetsInForce::toolLengthOffset() const {
    // FANUC offset memory holds numbers in the input unit of the moment (G20: inches); Z is never
    // a rotary axis (ModalInterpreter::axisUnit)
    const double unit = state_.inches() ? 25.4 : 1.0;
    switch (state_.group(8)) {
    case 43: return state_.lengthOffsetValue * unit;
    case 44: return -state_.lengthOffsetValue * unit;
    default: return 0.0;
    }
}

int OffsetsInForce::activeSlot() const {
    if (dialect_.id == gcode::DialectId::M350) {
        int slot = saturatingInt(parameters_.get(param::kCurrentWorkSystem));
        return (slot >= 0 && slot <= 6) ? slot : 1;
    }
    if (state_.additionalSystem > 0) {
        return WorkOffsets::additionalSlot(state_.additionalSystem);
    }
    return state_.group(14) - 53;
}

void OffsetsInForce::refresh() const {
    cache_.inputs = inputs();
    cache_.offset = compute();
    cache_.known = true;
}

machine::Axes OffsetsInForce::compute() const {
    machine::Axes offset = offsets_.slot(activeSlot()) + offsets_.slot(WorkOffsets::kG52) +
                           offsets_.slot(WorkOffsets::kCommon);
    if (dialect_.id == gcode::DialectId::Fanuc) {
        offset += offsets_.slot(WorkOffsets::kG92); // FANUC's G92 shifts the active system
    }
    offset(2) += toolZOffset(); // M350: work Z = machine Z - G54..G59 Z - tool Z offset
    offset(2) += toolLengthOffset();
    return offset;
}

} // namespace m350::interp
