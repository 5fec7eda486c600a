// The operator's keys wired to inputs: the external keys 1-6, extern START, PAUSE and E-stop
// (params 581-605). A key acts when its input becomes active; the E-stop acts while it is active,
// as a latched mushroom button keeps a real machine stopped. A key already active when it is wired
// (at power-on, or after its parameters change) acts at its next press.
#include "core/controller/OperatorInputs.h"

#include "core/params/IoPorts.h"
#include "core/machine/SimulatedMachine.h"
#include "core/params/ParameterNumbers.h"
#include "core/params/ParameterTable.h"

namespace m350::controller {

namespace {

using Kind = OperatorKey::Kind;

struct OperatorInput {
    int parameter; // the input triple's first parameter
    std::optional<Kind> kind; // none: the E-stop
    int key;
};

constexpr int kExternKey1Input = 581; // 581, 584, .. 596: external keys 1-6
constexpr int kExternPauseInput = 602;
constexpr int kExternEStopInput = 605;

constexpr std::array<OperatorInput, 9> kOperatorInputs{{
    {kExternKey1Input, Kind::ExternKey, 1},
    {kExternKey1Input + 3, Kind::ExternKey, 2},
    {kExternKey1Input + 6, Kind::ExternKey, 3},
    {kExternKey1Input + 9, Kind::ExternKey, 4},
    {kExternKey1Input + 12, Kind::ExternKey, 5},
    {kExternKey1Input + 15, Kind::ExternKey, 6},
    {param::kExternStartInput, Kind::Start, 0},
    {kExternPauseInput, Kind::Pause, 0},
    {kExternEStopInput, std::nullopt, 0},
}};

} // namespace

std::optional<std::string> OperatorInputs::watch(const params::ParameterTable& parameters,
                                                 machine::SimulatedMachine& machine, bool running) {
    std::optional<std::string> eStop;
    for (std::size_t i = 0; i < kOperatorInputs.size(); ++i) {
        const OperatorInput& input = kOperatorInputs[i];
        auto wired = params::wiredInput(parameters, input.parameter);
        const bool active = wired && machine.input(wired->pin) == wired->activeLevel;
        // a key just wired (or its level changed) is read as it stands: that is no press
        const int wiring = wired ? wired->pin * 2 + wired->activeLevel : -1;
        const bool pressed = active && !active_[i] && wiring == wiring_[i];
        active_[i] = active;
        wiring_[i] = wiring;
        if (!input.kind) {
            if (active) {
                eStop = params::inputName(wired->pin);
            }
            continue;
        }
        if (!pressed || (*input.kind == Kind::Start && running)) {
            continue;
        }
        if (keys_.size() == kQueue) {
            keys_.erase(keys_.begin());
        }
        keys_.push_back({*input.kind, input.key});
    }
    return eStop;
}

std::vector<OperatorKey> OperatorInputs::take() {
    std::vector<OperatorKey> keys;
    keys.swap(keys_);
    return keys;
}

} // namespace m350::controller
