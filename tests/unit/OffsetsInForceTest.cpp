// OffsetsInForce on its own: which offsets add up on each dialect, G43's length in the unit of
// the moment, and that the kept sum follows every change of what it is computed from (the offsets,
// the parameters, the modal state written in place).
#include "core/interp/OffsetsInForce.h"

#include "core/gcode/Dialect.h"
#include "core/params/ParameterNumbers.h"
#include "core/params/ParameterTable.h"
#include "core/tools/ToolData.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using interp::OffsetsInForce;
using interp::WorkOffsets;

TEST(OffsetsInForce, AFanucAddsTheSystemG52TheCommonOffsetG92AndTheLengthInTheUnitOfTheMoment) {
    params::ParameterTable parameters;
    WorkOffsets offsets;
    interp::ModalState state;
    OffsetsInForce inForce(gcode::Dialect::fanuc(), parameters, offsets, state);
    offsets.set(1, 0, 100.0);              // G54 X
    offsets.set(2, 0, 500.0);              // G55 X
    offsets.set(WorkOffsets::kG52, 0, 1.0);
    offsets.set(WorkOffsets::kCommon, 0, 0.5);
    offsets.set(WorkOffsets::kG92, 0, 20.0);
    EXPECT_EQ(inForce.activeSlot(), 1);
    EXPECT_DOUBLE_EQ(inForce.total()(0), 121.5);

    state.groups[14] = 55; // the interpreter writes its state in place
    EXPECT_EQ(inForce.activeSlot(), 2);
    EXPECT_DOUBLE_EQ(inForce.total()(0), 521.5);

    state.groups[8] = 43;
    state.lengthOffsetValue = 2.0;
    EXPECT_DOUBLE_EQ(inForce.total()(2), 2.0);
    state.groups[6] = 20; // G20: offset memory in inches
    EXPECT_DOUBLE_EQ(inForce.toolLengthOffset(), 50.8);
    EXPECT_DOUBLE_EQ(inForce.total()(2), 50.8);
    state.groups[8] = 44;
    EXPECT_DOUBLE_EQ(inForce.total()(2), -50.8);

    state.groups[14] = 54.1;
    state.additionalSystem = 2;
    offsets.setAdditionalCount(48);
    offsets.set(WorkOffsets::additionalSlot(2), 1, 7.0);
    EXPECT_EQ(inForce.activeSlot(), WorkOffsets::additionalSlot(2));
    EXPECT_DOUBLE_EQ(inForce.total()(1), 7.0);
}

TEST(OffsetsInForce, AnM350TakesItsSystemFromParam78AndTheToolsZOffsetButNotG92) {
    params::ParameterTable parameters;
    WorkOffsets offsets;
    interp::ModalState state;
    OffsetsInForce inForce(gcode::Dialect::m350(), parameters, offsets, state);
    offsets.set(WorkOffsets::kG92, 2, -40.0);
    offsets.set(3, 2, -100.0); // G56 Z
    parameters.set(param::kCurrentWorkSystem, 3);
    EXPECT_EQ(inForce.activeSlot(), 3);
    EXPECT_DOUBLE_EQ(inForce.total()(2), -100.0);

    parameters.set(param::kCurrentTool, 2);
    const int zParameter = *tools::m350ZParameter(2, parameters);
    parameters.set(zParameter, -55.5);
    EXPECT_EQ(inForce.currentTool(), 2);
    EXPECT_DOUBLE_EQ(inForce.toolZOffset(), -55.5);
    EXPECT_DOUBLE_EQ(inForce.total()(2), -155.5) << "the parameters' change is seen";

    parameters.set(param::kCurrentWorkSystem, 9);
    EXPECT_EQ(inForce.activeSlot(), 1) << "a system out of 0-6 reads as G54";
    parameters.set(param::kCurrentWorkSystem, 0);
    EXPECT_DOUBLE_EQ(inForce.total()(2), -40.0 - 55.5) << "the M350's G92 system is slot 0";
}

} // namespace
