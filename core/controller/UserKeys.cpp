// The keys an M350 owner assigns: K1-K7 on the panel, the external keys 1-6 on inputs, and the
// FUNC keys K01-K14 of the add-on keypad. Parameters say what each key does.
#include "core/controller/Controller.h"

#include "core/common/Numeric.h"
#include "core/params/ParameterNumbers.h"

namespace m350::controller {

namespace {

constexpr double kPanelKeyCodes = 1000; // above: the code of the panel key the K key stands for
constexpr int kFunctionKeys = 14;       // FUNC K01-K14 give M250-M263
constexpr int kFirstFunctionMCode = 250;
constexpr int kCustomMCodeVariable = 1996; // #1996: the M code ext_button.nc runs (`M#1996`)

std::string numberText(double v) {
    return v == static_cast<double>(saturatingInt(v)) ? std::to_string(saturatingInt(v)) : std::to_string(v);
}

} // namespace

Controller::KeyPress Controller::pressKey(int function, config::Hook hook, const std::string& key) {
    KeyPress press;
    const double value = config_.parameters.get(function);
    const int code = saturatingInt(value);
    if (value == 0.0) {
        if (!loadHook(hook)) {
            press.why = key + ": " + (diagnostics_.empty() ? std::string("not run") : diagnostics_.front().message);
            return press;
        }
        press.kind = KeyPress::Kind::Hook;
    } else if (value == code && code >= 1 && code <= machine::kOutputCount) {
        if (!manual_.setOutputByOperator(code, 1 - machine_.output(code))) {
            press.why = key + ": OUT" + std::to_string(code) + " cannot be switched while a program runs";
            return press;
        }
        press.kind = KeyPress::Kind::Output;
        press.value = code;
    } else if (value > kPanelKeyCodes) {
        press.kind = KeyPress::Kind::PanelKey;
        press.value = code;
    } else {
        press.why = key + ": parameter " + std::to_string(function) + " = " + numberText(value) +
                    " is no key function (0 runs " + std::string(config::hookFile(hook).fileName) + ", 1-" +
                    std::to_string(machine::kOutputCount) + " switches that output, above 1000 is a panel key)";
    }
    return press;
}

Controller::KeyPress Controller::pressUserKey(int key) {
    auto hook = config::userKeyHook(key);
    if (!hook) {
        return {KeyPress::Kind::Refused, 0, "K" + std::to_string(key) + ": the panel has K1-K7"};
    }
    return pressKey(param::kUserKeyFunction + key - 1, *hook, "K" + std::to_string(key));
}

Controller::KeyPress Controller::pressExternKey(int key) {
    auto hook = config::externKeyHook(key);
    if (!hook) {
        return {KeyPress::Kind::Refused, 0, "external key " + std::to_string(key) + ": there are keys 1-6"};
    }
    return pressKey(param::kExternKeyFunction + key - 1, *hook, "external key " + std::to_string(key));
}

bool Controller::loadFunctionKey(int key) {
    if (key < 1 || key > kFunctionKeys) {
        diagnostics_.assign(1, {gcode::Severity::Error, gcode::DiagnosticKind::Syntax, "", 0, 0,
                                "FUNC K" + std::to_string(key) + ": the keypad has K01-K14"});
        executor_.reset();
        return false;
    }
    const int code = kFirstFunctionMCode + key - 1;
    return loadHookOrMdi(config::Hook::ExtButton, {{kCustomMCodeVariable, code}}, {"M" + std::to_string(code)});
}

} // namespace m350::controller
