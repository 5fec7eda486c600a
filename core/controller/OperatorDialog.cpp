#include "core/controller/OperatorDialog.h"

#include "core/common/Numeric.h"

namespace m350::controller {

namespace {

constexpr double kMessageOnly = -5000; // `#1505 = -5000(text)`: a text to show, nothing to answer

} // namespace

void OperatorDialog::show(double kind, std::string_view text, bool operatorAnswers) {
    if (!operatorAnswers) {
        context_.post(message("notice_dialog_enter", {std::string(text)}));
        answer_ = 1;
        return;
    }
    if (kind == kMessageOnly) {
        context_.showStatus(std::string(text));
        return;
    }
    pending_ = Dialog{std::string(text), roundToInt(kind)};
    context_.trace("dialog: " + std::string(text));
}

void OperatorDialog::answer(bool enter) {
    if (!pending_) {
        return;
    }
    answer_ = enter ? 1 : 0;
    context_.post(message(enter ? "notice_dialog_enter" : "notice_dialog_esc", {pending_->text}));
    pending_.reset();
    context_.catchUpClock(); // the clock ran while the operator read it
}

} // namespace m350::controller
