#pragma once

#include "core/common/Message.h"
#include "core/config/InterfaceSignals.h"
#include "core/macro/Value.h"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace m350::machine {
class ScanMachine;
}

namespace m350::controller {

// The PMC's side of a FANUC's custom macro interface signals, as the machine folder wires them
// (config::InterfaceSignals): it puts the inputs UI000-UI015 together for #1000-#1015 and #1032,
// keeps the outputs the macros write (#1100-#1115 and #1132: UO000-UO015; #1133: UO100-UO131)
// and switches the machine outputs they are wired to.
class InterfaceSignalsPmc {
  public:
    // What the ladder reads; all of it belongs to the Controller and outlives this.
    struct Context {
        const config::InterfaceSignals& wiring;
        machine::ScanMachine& machine;      // outputs go through it, so a 断点 scan keeps them
        std::function<int(int)> readInput;  // an input as macros read it (the sensor-wait watch sees it)
        std::function<int()> commandedTool; // the T code of the program
        std::function<int()> spindleTool;   // the tool the PMC believes in the spindle (M85)
        std::function<std::uint16_t()> spindleLoad; // the load register
        std::function<bool()> toolChangeSignal;      // tool life's TLCH
        std::function<bool()> newToolSignal;         // tool life's TLNW
    };

    explicit InterfaceSignalsPmc(Context context) : context_(std::move(context)) {}

    macro::Value input(int bit) const;    // #1000 + bit
    macro::Value inputs() const;          // #1032
    macro::Value output(int bit) const;   // #1100 + bit
    macro::Value outputs(int word) const; // #1132 (word 0), #1133 (word 1)
    // A macro's write; what is wrong with the value, if anything.
    std::optional<Message> setOutput(int bit, double value);
    std::optional<Message> setOutputs(int word, double value);

  private:
    int inputBit(int bit) const;
    void drive(int pin, int level);

    Context context_;
    std::uint16_t outputs_ = 0;    // UO000-UO015
    std::int32_t wideOutputs_ = 0; // UO100-UO131, as #1133 was written
};

} // namespace m350::controller
