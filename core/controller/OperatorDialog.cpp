// The operator dialog (#1505): a run with a person at the panel holds until the dialog is
// answered; a run without one answers Enter at once and says so.
#include "core/controller/Controller.h"

#include "core/common/Numeric.h"

namespace m350::controller {

namespace {

constexpr double kMessageOnly = -5000; // `#1505 = -5000(text)`: a text to show, nothing to answer

} // namespace

std::optional<std::string> Controller::showDialog(double kind, std::string_view text) {
    if (!operatorAnswers()) {
        status_.postMessage(std::string(text) + " [dialog answered: Enter]");
        dialogAnswer_ = 1;
        return std::nullopt;
    }
    if (kind == kMessageOnly) {
        status_.showStatus(std::string(text));
        status_.postMessage(std::string(text));
        return std::nullopt;
    }
    // advance() executes no further block while the dialog is pending
    pendingDialog_ = Dialog{std::string(text), roundToInt(kind)};
    if (status_.trace()) {
        status_.trace()->message(machine_.time(), "dialog: " + std::string(text), status_.source());
    }
    return std::nullopt;
}

void Controller::answerDialog(bool enter) {
    if (!pendingDialog_) {
        return;
    }
    dialogAnswer_ = enter ? 1 : 0;
    status_.postMessage(pendingDialog_->text + (enter ? " [dialog answered: Enter]" : " [dialog answered: Esc]"));
    pendingDialog_.reset();
    if (machine_.time() < displayTime_) {
        machine_.blockTime(displayTime_ - machine_.time()); // the clock ran while the operator read it
    }
}

} // namespace m350::controller
