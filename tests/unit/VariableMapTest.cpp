// The variable catalogue: what each representative number is in each dialect.
#include "core/gcode/Dialect.h"
#include "core/macro/VariableMap.h"

#include <gtest/gtest.h>

#include <climits>
#include <set>
#include <string>
#include <string_view>

using m350::gcode::Dialect;
using m350::macro::kindName;
using m350::macro::VariableInfo;
using m350::macro::VariableKind;
using m350::macro::VariableMap;

namespace {

constexpr int kAny = INT_MIN; // the index carries no meaning for this kind

struct Expect {
    int number;
    VariableKind kind;
    bool readOnly;
    int index;
};

void checkAll(const VariableMap& map, std::initializer_list<Expect> expectations) {
    for (const Expect& e : expectations) {
        VariableInfo info = map.describe(e.number);
        SCOPED_TRACE("#" + std::to_string(e.number) + " described as " + map.describeText(e.number));
        EXPECT_EQ(info.kind, e.kind);
        EXPECT_EQ(info.readOnly, e.readOnly);
        if (e.index != kAny) {
            EXPECT_EQ(info.index, e.index);
        }
    }
}

using K = VariableKind;

// ---------------------------------------------------------------- M350

TEST(VariableMapM350, LocalsAndCommon) {
    VariableMap map(Dialect::m350());
    checkAll(map, {
        {0, K::Local, false, kAny},
        {1, K::Local, false, kAny},
        {49, K::Local, false, kAny},
        {50, K::Common, false, kAny},
        {100, K::Common, false, kAny},
        {499, K::Common, false, kAny},
    });
}

TEST(VariableMapM350, ParametersAreNumberMinus500) {
    VariableMap map(Dialect::m350());
    checkAll(map, {
        {500, K::Parameter, false, 0},
        {561, K::Parameter, false, 61},
        {578, K::Parameter, false, 78}, // current work system
        {629, K::Parameter, false, 129},
        {799, K::Parameter, false, 299},
        {845, K::Parameter, false, 345}, // between the offsets and the work positions
        {1300, K::Parameter, false, 800},
        {1301, K::Parameter, false, 801},
        {1430, K::Parameter, false, 930},
        {1499, K::Parameter, false, 999},
    });
}

TEST(VariableMapM350, WorkOffsetsAndPositions) {
    VariableMap map(Dialect::m350());
    // index = slot * 8 + axis; slot 0 = G92, 1..6 = G54..G59, 8 = common
    checkAll(map, {
        {800, K::WorkOffset, false, 0},
        {804, K::WorkOffset, false, 4},
        {805, K::WorkOffset, false, 8},   // G54 X
        {806, K::WorkOffset, false, 9},   // G54 Y
        {807, K::WorkOffset, false, 10},  // G54 Z
        {810, K::WorkOffset, false, 16},  // G55 X
        {830, K::WorkOffset, false, 48},  // G59 X
        {840, K::WorkOffset, false, 64},  // common X
        {844, K::WorkOffset, false, 68},
        {850, K::WorkPosition, true, 8},  // work position in G54
        {852, K::WorkPosition, true, 10},
        {879, K::WorkPosition, true, 52},
        {880, K::MachinePosition, false, 0}, // writable: a hook copies Y to A so
        {882, K::MachinePosition, false, 2},
        {884, K::MachinePosition, false, 4},
        {885, K::WorkPosition, true, 0},  // in the G92 system
        {889, K::WorkPosition, true, 4},
    });
}

TEST(VariableMapM350, SystemMessagesAndIo) {
    VariableMap map(Dialect::m350());
    checkAll(map, {
        {1500, K::System, false, kAny},
        {1503, K::Message, false, kAny},
        {1504, K::System, false, kAny},
        {1505, K::Dialog, false, kAny},
        {1510, K::System, false, kAny},
        {1515, K::Homed, false, 0},
        {1519, K::Homed, false, 4},
        {1520, K::Input, true, 1},
        {1530, K::Input, true, 11},
        {1543, K::Input, true, 24},
        {1544, K::System, false, kAny},
        {1552, K::Output, false, 1},
        {1553, K::Output, false, 2},
        {1572, K::Output, false, 21},
        {1573, K::System, false, kAny},
        {1920, K::ProbeResult, false, 0},
        {1924, K::ProbeResult, false, 4},
        {1925, K::ProbeResult, true, 5},
        {1929, K::ProbeResult, true, 9},
        {2999, K::System, false, kAny},
    });
}

TEST(VariableMapM350, UndefinedNumbers) {
    VariableMap map(Dialect::m350());
    for (int n : {-1, 3001, 4001, 5021, 9999, 10000, 123456}) {
        EXPECT_EQ(map.describe(n).kind, K::Undefined) << "#" << n;
    }
}

// A simulator extra: FANUC's #3000 macro alarm, which our tool-setting macros raise.
TEST(VariableMapM350, Variable3000IsTheMacroAlarm) {
    VariableMap map(Dialect::m350());
    EXPECT_EQ(map.describe(3000).kind, K::Alarm);
    EXPECT_FALSE(map.describe(3000).readOnly);
}

TEST(VariableMapM350, DescribeText) {
    VariableMap map(Dialect::m350());
    EXPECT_EQ(map.describeText(1300), "#1300 (parameter 800)");
    EXPECT_EQ(map.describeText(1520), "#1520 (input IN01)");
    EXPECT_EQ(map.describeText(1530), "#1530 (input IN11)");
    EXPECT_EQ(map.describeText(1552), "#1552 (output OUT01)");
    EXPECT_EQ(map.describeText(1572), "#1572 (output OUT21)");
    EXPECT_EQ(map.describeText(1), "#1 (local)");
    EXPECT_EQ(map.describeText(880), "#880 (machine position)");
    EXPECT_EQ(map.describeText(805), "#805 (work offset)");
    EXPECT_EQ(map.describeText(3000), "#3000 (alarm)");
    EXPECT_EQ(map.describeText(3001), "#3001 (undefined)");
}

// ---------------------------------------------------------------- FANUC

TEST(VariableMapFanuc, NullLocalsCommonRetained) {
    VariableMap map(Dialect::fanuc());
    checkAll(map, {
        {0, K::Null, true, kAny},
        {1, K::Local, false, kAny},
        {33, K::Local, false, kAny},
        {100, K::Common, false, kAny},
        {199, K::Common, false, kAny},
        {500, K::Retained, false, kAny},
        {999, K::Retained, false, kAny},
    });
}

TEST(VariableMapFanuc, SystemVariables) {
    VariableMap map(Dialect::fanuc());
    checkAll(map, {
        {1000, K::InterfaceInput, true, 0},
        {1002, K::InterfaceInput, true, 2},
        {1015, K::InterfaceInput, true, 15},
        {1032, K::InterfaceInputs, true, 0},
        {1100, K::InterfaceOutput, false, 0},
        {1115, K::InterfaceOutput, false, 15},
        {1132, K::InterfaceOutputs, false, 0},
        {1133, K::InterfaceOutputs, false, 1},
        {3003, K::OperationControl, false, 3},
        {3004, K::OperationControl, false, 4},
        {3000, K::Alarm, false, kAny},
        {3006, K::StopMessage, false, kAny},
        {4001, K::ModalGroup, true, 1},
        {4003, K::ModalGroup, true, 3},
        {4006, K::ModalGroup, true, 6},
        {4014, K::ModalGroup, true, 14},
        {4022, K::ModalGroup, true, 22},
        {4109, K::ModalWord, true, 109},
        {4120, K::ModalWord, true, 120},
        {5001, K::BlockEnd, true, 0},
        {5003, K::BlockEnd, true, 2},
        {5021, K::MachinePosition, true, 0},
        {5023, K::MachinePosition, true, 2},
        {5025, K::MachinePosition, true, 4},
        {5041, K::WorkPosition, true, -8},
        {5061, K::SkipPosition, true, 0},
        {5201, K::WorkOffset, false, 64}, // EXT (common) X
        {5221, K::WorkOffset, false, 8},  // G54 X
        {5223, K::WorkOffset, false, 10}, // G54 Z
        {5241, K::WorkOffset, false, 16}, // G55 X
        {5321, K::WorkOffset, false, 48}, // G59 X
        {5325, K::WorkOffset, false, 52},
    });
}

TEST(VariableMapFanuc, UndefinedNumbers) {
    VariableMap map(Dialect::fanuc());
    // gaps between the ranges, the M350's own numbers, the last number and beyond
    for (int n : {-1, 34, 50, 99, 200, 499, 1016, 1031, 1033, 1116, 1131, 1134, 1300, 1503, 1520, 1552, 3005, 4000,
                  5000, 5026, 5206, 5326, 9999, 10000}) {
        EXPECT_EQ(map.describe(n).kind, K::Undefined) << "#" << n << " is " << map.describeText(n);
    }
}

TEST(VariableMapFanuc, DescribeText) {
    VariableMap map(Dialect::fanuc());
    EXPECT_EQ(map.describeText(0), "#0 (null (#0, always vacant))");
    EXPECT_EQ(map.describeText(5021), "#5021 (machine position)");
    EXPECT_EQ(map.describeText(4003), "#4003 (modal group)");
    EXPECT_EQ(map.describeText(9999), "#9999 (undefined)");
}

TEST(VariableMapKinds, EveryKindHasADistinctName) {
    std::set<std::string_view> names;
    for (int k = 0; k <= static_cast<int>(K::System); ++k) {
        std::string_view name = kindName(static_cast<K>(k));
        EXPECT_FALSE(name.empty());
        EXPECT_TRUE(names.insert(name).second) << "duplicate kind name " << name;
    }
    EXPECT_EQ(kindName(K::Parameter), "parameter");
    EXPECT_EQ(kindName(K::Input), "input");
    EXPECT_EQ(kindName(K::Output), "output");
}

} // namespace
