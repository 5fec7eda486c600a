#pragma once

#include <QString>

#include <functional>
#include <optional>

namespace m350::ui {

// The panel's question box as pages and the dispatcher see it: a question asked (with a line of
// text to type or not) and answered with Enter or Esc. The panel's PromptBox is the one there is;
// pages reach it through their PanelContext, keys through the dispatcher.
class PanelPrompt {
public:
    using Answer = std::function<void(std::optional<QString>)>; // nullopt: Esc

    // `secret`: the typed text shows as dots (passwords).
    virtual void ask(const QString& question, bool withText, const QString& initial, Answer answer,
                     bool secret = false) = 0;
    virtual bool active() const = 0;
    virtual void type(const QString& text) = 0;
    virtual void backspace() = 0;
    virtual void confirm() = 0; // Enter
    virtual void cancel() = 0;  // Esc

protected:
    ~PanelPrompt() = default;
};

} // namespace m350::ui
