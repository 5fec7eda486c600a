#include "core/controller/InterfaceSignalsPmc.h"

#include "core/machine/ScanMachine.h"

#include <cmath>
#include <cstdio>

namespace m350::controller {

namespace {

using Source = config::InterfaceSignals::Source;

constexpr double kMostWide = 99999999.0; // #1133 takes -99999999 to 99999999

} // namespace

int InterfaceSignalsPmc::inputBit(int bit) const {
    if (context_.wiring.inputsAreSpindleLoad) {
        return (context_.spindleLoad() >> bit) & 1;
    }
    const config::InterfaceSignals::Bit& wired = context_.wiring.inputs[static_cast<std::size_t>(bit)];
    switch (wired.source) {
    case Source::None:
        return 0;
    case Source::Input:
        return context_.readInput(wired.pin) != 0 ? 1 : 0;
    case Source::CommandedToolInSpindle:
        return context_.commandedTool() == context_.spindleTool() ? 1 : 0;
    case Source::SpindleEmpty:
        return context_.spindleTool() == 0 ? 1 : 0;
    case Source::T0Commanded:
        return context_.commandedTool() == 0 ? 1 : 0;
    case Source::ToolChangeSignal:
        return context_.toolChangeSignal() ? 1 : 0;
    case Source::NewToolSignal:
        return context_.newToolSignal() ? 1 : 0;
    }
    return 0;
}

macro::Value InterfaceSignalsPmc::input(int bit) const {
    return macro::Value::of(inputBit(bit));
}

macro::Value InterfaceSignalsPmc::inputs() const {
    if (context_.wiring.inputsAreSpindleLoad) {
        return macro::Value::of(context_.spindleLoad());
    }
    int word = 0;
    for (int bit = 0; bit < config::InterfaceSignals::kInputs; ++bit) {
        word |= inputBit(bit) << bit;
    }
    return macro::Value::of(word);
}

macro::Value InterfaceSignalsPmc::output(int bit) const {
    return macro::Value::of((outputs_ >> bit) & 1);
}

macro::Value InterfaceSignalsPmc::outputs(int word) const {
    return macro::Value::of(word == 0 ? static_cast<double>(outputs_) : static_cast<double>(wideOutputs_));
}

void InterfaceSignalsPmc::drive(int pin, int level) {
    if (pin > 0) {
        context_.machine.setOutput(pin, level);
    }
}

std::optional<Message> InterfaceSignalsPmc::setOutput(int bit, double value) {
    if (value != 0.0 && value != 1.0) {
        char text[32];
        std::snprintf(text, sizeof text, "%.10g", value);
        return message("interface_output_bit", {std::to_string(1100 + bit), text});
    }
    const int level = value != 0.0 ? 1 : 0;
    outputs_ = static_cast<std::uint16_t>((outputs_ & ~(1u << bit)) | (static_cast<unsigned>(level) << bit));
    drive(context_.wiring.outputs[static_cast<std::size_t>(bit)], level);
    return std::nullopt;
}

std::optional<Message> InterfaceSignalsPmc::setOutputs(int word, double value) {
    const double most = word == 0 ? 65535.0 : kMostWide;
    const double least = word == 0 ? 0.0 : -kMostWide;
    if (value != std::floor(value) || value < least || value > most) {
        char text[3][32];
        std::snprintf(text[0], sizeof text[0], "%.10g", value);
        std::snprintf(text[1], sizeof text[1], "%.10g", least);
        std::snprintf(text[2], sizeof text[2], "%.10g", most);
        return message("interface_outputs_range", {std::to_string(1132 + word), text[0], text[1], text[2]});
    }
    if (word == 0) {
        outputs_ = static_cast<std::uint16_t>(value);
        for (int bit = 0; bit < config::InterfaceSignals::kOutputs; ++bit) {
            drive(context_.wiring.outputs[static_cast<std::size_t>(bit)], (outputs_ >> bit) & 1);
        }
        return std::nullopt;
    }
    wideOutputs_ = static_cast<std::int32_t>(value);
    const auto bits = static_cast<std::uint32_t>(wideOutputs_); // a negative number sets bit 31
    for (int bit = 0; bit < config::InterfaceSignals::kWideOutputs; ++bit) {
        drive(context_.wiring.wideOutputs[static_cast<std::size_t>(bit)],
              static_cast<int>((bits >> bit) & 1u));
    }
    return std::nullopt;
}

} // namespace m350::controller
