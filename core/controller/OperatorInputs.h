#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace m350::params {
class ParameterTable;
}

namespace m350::machine {
class SimulatedMachine;
}

namespace m350::controller {

// A press of an operator's key wired to an input, queued for the panel, which acts on it as on its
// own key.
struct OperatorKey {
    enum class Kind { Start, Pause, ExternKey } kind;
    int key = 0; // ExternKey: 1-6
    bool operator==(const OperatorKey&) const = default;
};

// The operator's keys wired to inputs, read at every advance(): the extern E-stop (param 605)
// stops the machine while its input is active (RESET does not clear it while the key is held); a
// press of the extern START (599), PAUSE (602) or an external key 1-6 (581-596) is queued for the
// panel. START is no key press while a program runs: macros read it (the virtual-tool prompt). At
// most kQueue presses wait; older ones are dropped.
class OperatorInputs {
public:
    static constexpr std::size_t kQueue = 16;

    // Reads the inputs as they stand; the extern E-stop's input ("IN21") while it is active.
    std::optional<std::string> watch(const params::ParameterTable& parameters, machine::SimulatedMachine& machine,
                                     bool running);
    std::vector<OperatorKey> take();

private:
    static constexpr std::size_t kInputs = 9;
    std::array<bool, kInputs> active_{}; // the operator inputs' last state
    std::array<int, kInputs> wiring_{};  // and the pin and level each was read on
    std::vector<OperatorKey> keys_;
};

} // namespace m350::controller
