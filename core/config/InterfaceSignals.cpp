#include "core/config/InterfaceSignals.h"

#include "core/config/TomlReading.h"
#include "core/machine/MachineTypes.h"

#include <charconv>
#include <string>
#include <string_view>

namespace m350::config {

namespace {

using toml_reading::fail;

// "IN05" / "OUT07": the pin, or 0 when `text` is not `prefix` and a number within 1..count.
int pinNamed(std::string_view text, std::string_view prefix, int count) {
    if (text.substr(0, prefix.size()) != prefix || text.size() == prefix.size()) {
        return 0;
    }
    int pin = 0;
    const std::string_view digits = text.substr(prefix.size());
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), pin);
    return ec == std::errc() && end == digits.data() + digits.size() && pin >= 1 && pin <= count ? pin : 0;
}

// "UI007" -> 7, "UO103" -> 103; -1 when the key is no such name.
int signalNumber(std::string_view key, std::string_view prefix) {
    if (key.substr(0, prefix.size()) != prefix || key.size() != prefix.size() + 3) {
        return -1;
    }
    int number = 0;
    auto [end, ec] = std::from_chars(key.data() + prefix.size(), key.data() + key.size(), number);
    return ec == std::errc() && end == key.data() + key.size() ? number : -1;
}

} // namespace

void readInterfaceSignals(const std::filesystem::path& file, const toml::table& machine,
                          InterfaceSignals& out) {
    const toml::table* table = machine["interface_signals"].as_table();
    if (!table) {
        return;
    }
    using Source = InterfaceSignals::Source;
    bool bitsWired = false;
    toml::source_region wordAt{};
    for (auto&& [key, node] : *table) {
        const std::string_view k = key.str();
        const std::string name = "[interface_signals] " + std::string(k);
        auto text = node.value<std::string>();
        if (!text) {
            fail(file, message("config_signal_quoted", {name}), node.source());
        }
        if (k == "UI") {
            if (*text != "spindle_load") {
                fail(file, message("config_signal_ui_all", {name, *text}), node.source());
            }
            out.inputsAreSpindleLoad = true;
            wordAt = node.source();
            continue;
        }
        if (const int bit = signalNumber(k, "UI"); bit >= 0) {
            if (bit >= InterfaceSignals::kInputs) {
                fail(file, message("config_signal_ui_range", {name}), key.source());
            }
            InterfaceSignals::Bit& wired = out.inputs[static_cast<std::size_t>(bit)];
            if (const int pin = pinNamed(*text, "IN", machine::kInputCount)) {
                wired = {Source::Input, pin};
            } else if (*text == "commanded_tool_in_spindle") {
                wired = {Source::CommandedToolInSpindle, 0};
            } else if (*text == "spindle_empty") {
                wired = {Source::SpindleEmpty, 0};
            } else if (*text == "t0_commanded") {
                wired = {Source::T0Commanded, 0};
            } else if (*text == "tool_change_signal") {
                wired = {Source::ToolChangeSignal, 0};
            } else if (*text == "new_tool_signal") {
                wired = {Source::NewToolSignal, 0};
            } else {
                fail(file, message("config_signal_input_source", {name, *text, std::to_string(machine::kInputCount)}),
                     node.source());
            }
            bitsWired = true;
            continue;
        }
        const int bit = signalNumber(k, "UO");
        const bool narrow = bit >= 0 && bit < InterfaceSignals::kOutputs;
        const bool wide = bit >= 100 && bit < 100 + InterfaceSignals::kWideOutputs;
        if (!narrow && !wide) {
            fail(file, message("config_signal_name", {name}), key.source());
        }
        const int pin = pinNamed(*text, "OUT", machine::kOutputCount);
        if (pin == 0) {
            fail(file, message("config_signal_output_pin", {name, *text, std::to_string(machine::kOutputCount)}),
                 node.source());
        }
        (narrow ? out.outputs[static_cast<std::size_t>(bit)]
                : out.wideOutputs[static_cast<std::size_t>(bit - 100)]) = pin;
    }
    if (out.inputsAreSpindleLoad && bitsWired) {
        fail(file, message("config_signal_ui_and_bits"), wordAt);
    }
}

} // namespace m350::config
