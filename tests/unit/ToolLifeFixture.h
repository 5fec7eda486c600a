#pragma once

// Machines with tool life groups for the tool life tests, and what a run left a tool's used life.
#include "RunProgram.h"

namespace m350::test {

inline tools::LifeGroup group(int number, int life, tools::LifeKind kind, std::vector<tools::LifeTool> list) {
    tools::LifeGroup g;
    g.number = number;
    g.life = life;
    g.kind = kind;
    g.tools = std::move(list);
    return g;
}

// Group 1: T11 (H11 D31) and T12 (H12 D32), 3 uses each; group 2: T21 (H21 D41), 1 minute. The
// ladder gives TLCH and TLNW to macros as #1003 and #1004, as the bundled fanuc-0i wires them.
inline config::MachineConfig fanucWithGroups(int usedByT11 = 0) {
    config::MachineConfig config = fanucMachine();
    using Source = config::InterfaceSignals::Source;
    config.interfaceSignals.inputs[3] = {Source::ToolChangeSignal, 0};
    config.interfaceSignals.inputs[4] = {Source::NewToolSignal, 0};
    config.toolLife.putGroup(group(1, 3, tools::LifeKind::Count, {{11, 11, 31, usedByT11}, {12, 12, 32, 0}}));
    config.toolLife.putGroup(group(2, 1, tools::LifeKind::Minutes, {{21, 21, 41, 0}}));
    return config;
}

inline int used(const ProgramRun& run, int groupNumber, int tool) {
    const tools::LifeGroup* g = run.controller->toolLife().manager().data().group(groupNumber);
    EXPECT_NE(g, nullptr);
    for (const tools::LifeTool& t : g ? g->tools : std::vector<tools::LifeTool>{}) {
        if (t.tool == tool) {
            return t.used;
        }
    }
    ADD_FAILURE() << "no T" << tool << " in group " << groupNumber;
    return -1;
}

} // namespace m350::test
