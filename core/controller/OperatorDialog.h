#pragma once

#include "core/common/Message.h"

#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace m350::controller {

// The operator dialog (#1505 = kind(text)): with RunSettings::operatorPresent the run holds after
// the block that wrote #1505 until answer(); #1505 then reads 1 for Enter and 0 for Esc.
// `#1505 = -5000(text)` only shows the text. Without an operator (and in run(), or a hook run to its
// end) every dialog is answered with Enter at once and the messages say so.
class OperatorDialog {
public:
    struct Dialog {
        std::string text;
        int kind;
    };
    // What the dialog tells the controller that owns it; all of it outlives the dialog.
    struct Context {
        std::function<void(const Message&)> post;    // a line of the run's messages
        std::function<void(std::string)> showStatus; // the status line (as #1503 sets it) and a message
        std::function<void(std::string)> trace;      // a trace message at the line executing now
        std::function<void()> catchUpClock;          // the machine's clock to the display's
    };

    explicit OperatorDialog(Context context) : context_(std::move(context)) {}

    // `#1505 = kind(text)`; `operatorAnswers`: a person at the panel answers it.
    void show(double kind, std::string_view text, bool operatorAnswers);
    void answer(bool enter);
    // The dialog no longer waits (start, reset, an alarm).
    void clear() { pending_.reset(); }
    // The dialog the run waits on; advance() executes no further block while there is one.
    const std::optional<Dialog>& pending() const { return pending_; }
    // What #1505 reads: the last answer.
    double lastAnswer() const { return answer_; }

private:
    Context context_;
    double answer_ = 0.0;
    std::optional<Dialog> pending_;
};

} // namespace m350::controller
