#pragma once

#include "core/controller/InputWatch.h"
#include "core/controller/KeyPress.h"
#include "core/controller/OperatorDialog.h"
#include "core/controller/OperatorInputs.h"
#include "core/controller/RunSettings.h"
#include "core/controller/SensorWatch.h"
#include "core/controller/UserKeys.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace m350::controller {

// The operator at the panel as the run sees them: the dialogs a macro asks (OperatorDialog), the
// keys wired to inputs (OperatorInputs), the keys the owner assigns (UserKeys) and the inputs a
// macro waits on (InputWatch). The panel reaches it through Controller::operatorPanel(); the
// controller tells it when nobody is at the panel (run(), a hook run to its end): then every
// dialog is answered with Enter and the extern START is pressed when a macro waits for it.
class OperatorPanel {
public:
    // What the panel reads of the controller that owns it.
    struct Context {
        const RunSettings& settings;   // operatorPresent
        std::function<bool()> running; // a program runs (not held, not stopped)
    };

    OperatorPanel(Context context, OperatorDialog::Context dialog, UserKeys::Context keys, InputWatch::Context inputs)
        : context_(std::move(context)), dialog_(std::move(dialog)), keys_(std::move(keys)), inputWatch_(std::move(inputs)) {}

    // The operator dialog the run waits on (OperatorDialog.h), and the operator's answer.
    using Dialog = OperatorDialog::Dialog;
    std::optional<Dialog> pendingDialog() const { return dialog_.pending(); }
    void answerDialog(bool enter) { dialog_.answer(enter); }
    // K1-K7, the external keys 1-6, FUNC K01-K14 (UserKeys.h).
    KeyPress pressUserKey(int key) { return keys_.pressUserKey(key); }
    KeyPress pressExternKey(int key) { return keys_.pressExternKey(key); }
    bool loadFunctionKey(int key) { return keys_.loadFunctionKey(key); }
    // The presses of the keys wired to inputs since the last call (OperatorInputs.h).
    static constexpr std::size_t kOperatorKeyQueue = OperatorInputs::kQueue;
    std::vector<OperatorKey> takeOperatorKeys() { return inputs_.take(); }
    void pressExternStart() { inputWatch_.pressExternStart(); }
    // A macro waiting for a sensor while the program runs; the wait ends in an alarm after
    // RunSettings::sensorTimeout.
    std::optional<SensorWait> sensorWait() const;

    // The controller's side.
    // Nobody at the panel: dialogs are answered at once, START is pressed when a macro awaits it.
    void setUnattended(bool unattended) { unattended_ = unattended; }
    bool unattended() const { return unattended_; }
    // `#1505 = kind(text)`, and what #1505 reads.
    void showDialog(double kind, std::string_view text) { dialog_.show(kind, text, operatorAnswers()); }
    double dialogAnswer() const { return dialog_.lastAnswer(); }
    bool dialogPending() const { return dialog_.pending().has_value(); }
    void clearDialog() { dialog_.clear(); }
    // A macro read input `pin` (InputWatch::read; throws the sensor-timeout alarm).
    void readInput(int pin, int level) { inputWatch_.read(pin, level, unattended_); }
    void clearSensorWait() { inputWatch_.clear(); }
    // Reads the keys wired to inputs; the extern E-stop's input while it is active.
    std::optional<std::string> watchInputs(const params::ParameterTable& parameters, machine::SimulatedMachine& machine,
                                           bool running) {
        return inputs_.watch(parameters, machine, running);
    }

private:
    bool operatorAnswers() const { return context_.settings.operatorPresent && !unattended_; }

    Context context_;
    OperatorDialog dialog_;
    OperatorInputs inputs_;
    UserKeys keys_;
    InputWatch inputWatch_;
    bool unattended_ = false;
};

} // namespace m350::controller
