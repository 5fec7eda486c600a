// The keys an M350 owner assigns: K1-K7 on the panel, the external keys 1-6 on inputs, and the
// FUNC keys K01-K14 of the add-on keypad. Parameters say what each key does.
#include "core/controller/UserKeys.h"

#include "core/common/Numeric.h"
#include "core/machine/MachineTypes.h"
#include "core/params/ParameterNumbers.h"
#include "core/params/ParameterTable.h"

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

KeyPress UserKeys::pressKey(int function, config::Hook hook, const std::string& key) {
    KeyPress press;
    const double value = context_.parameters.get(function);
    const int code = saturatingInt(value);
    if (value == 0.0) {
        if (!context_.loadHook(hook)) {
            const std::vector<gcode::Diagnostic>& why = context_.diagnostics();
            press.why = why.empty() ? message("key_not_run", {key})
                                    : message("key_refused", {key, bilingual(gcode::diagnosticText(why.front(), MessageLanguage::English),
                                                                             gcode::diagnosticText(why.front(), MessageLanguage::Chinese))});
            return press;
        }
        press.kind = KeyPress::Kind::Hook;
    } else if (value == code && code >= 1 && code <= machine::kOutputCount) {
        if (!context_.switchOutput(code, 1 - context_.output(code))) {
            press.why = message("key_output_running", {key, std::to_string(code)});
            return press;
        }
        press.kind = KeyPress::Kind::Output;
        press.value = code;
    } else if (value > kPanelKeyCodes) {
        press.kind = KeyPress::Kind::PanelKey;
        press.value = code;
    } else {
        press.why = message("key_no_function", {key, std::to_string(function), numberText(value),
                                                std::string(config::hookFile(hook).fileName),
                                                std::to_string(machine::kOutputCount)});
    }
    return press;
}

KeyPress UserKeys::pressUserKey(int key) {
    auto hook = config::userKeyHook(key);
    if (!hook) {
        return {KeyPress::Kind::Refused, 0, message("key_user_range", {std::to_string(key)})};
    }
    return pressKey(param::kUserKeyFunction + key - 1, *hook, "K" + std::to_string(key));
}

KeyPress UserKeys::pressExternKey(int key) {
    auto hook = config::externKeyHook(key);
    if (!hook) {
        return {KeyPress::Kind::Refused, 0, message("key_extern_range", {std::to_string(key)})};
    }
    return pressKey(param::kExternKeyFunction + key - 1, *hook,
                    bilingual("external key " + std::to_string(key), "外部按键" + std::to_string(key)));
}

bool UserKeys::loadFunctionKey(int key) {
    if (key < 1 || key > kFunctionKeys) {
        context_.refuseLoad("FUNC K" + std::to_string(key) + ": the keypad has K01-K14");
        return false;
    }
    const int code = kFirstFunctionMCode + key - 1;
    return context_.loadHookOrMdi(config::Hook::ExtButton, {{kCustomMCodeVariable, code}}, {"M" + std::to_string(code)});
}

} // namespace m350::controller
