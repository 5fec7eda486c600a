#pragma once

#include "core/files/Toml.h"

#include <array>
#include <cstdint>
#include <filesystem>

namespace m350::config {

// A FANUC's custom macro interface signals as the PMC's ladder wires them to the machine
// (machine.toml [interface_signals]): what it puts on the inputs UI000-UI015 (G54-G55), which
// macros read as #1000-#1015 and all sixteen at once as #1032, and where the outputs the macros
// write go: UO000-UO015 (F54-F55, #1100-#1115, #1132 all sixteen) and UO100-UO131 (F56-F59, #1133
// all thirty-two).
//   UI000 = "IN05"                        the level of an input
//   UI000 = "commanded_tool_in_spindle"   the umbrella paper's G54.0: the T code is the spindle's tool
//   UI001 = "spindle_empty"               G54.1: the spindle holds no tool
//   UI002 = "t0_commanded"                G54.2: T0 was commanded
//   UI003 = "tool_change_signal"          tool life's TLCH (F064#0): a group has every tool spent
//   UI004 = "new_tool_signal"             tool life's TLNW (F064#1): the T moved on to a sister tool
//   UI = "spindle_load"                   all sixteen: the spindle load register (the breakage article's
//                                         R1212-R1213 copied to G54-G55)
//   UO000 = "OUT07", UO100 = "OUT08"      the output the signal switches
// A signal the folder does not wire reads 0 (inputs) or is kept for the macro to read back (outputs).
struct InterfaceSignals {
    enum class Source : std::uint8_t {
        None,
        Input,
        CommandedToolInSpindle,
        SpindleEmpty,
        T0Commanded,
        ToolChangeSignal,
        NewToolSignal
    };
    struct Bit {
        Source source = Source::None;
        int pin = 0; // Source::Input: IN01-IN24
    };
    static constexpr int kInputs = 16;      // UI000-UI015
    static constexpr int kOutputs = 16;     // UO000-UO015
    static constexpr int kWideOutputs = 32; // UO100-UO131

    std::array<Bit, kInputs> inputs{};
    bool inputsAreSpindleLoad = false;           // UI = "spindle_load"
    std::array<int, kOutputs> outputs{};         // OUTnn each drives, 0 none
    std::array<int, kWideOutputs> wideOutputs{}; // UO100-UO131
};

// Reads machine.toml's [interface_signals] into `out`; a key or value it cannot use fails with
// file:line:col.
void readInterfaceSignals(const std::filesystem::path& file, const toml::table& machine,
                          InterfaceSignals& out);

} // namespace m350::config
