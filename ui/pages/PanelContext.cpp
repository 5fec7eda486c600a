#include "ui/pages/PanelContext.h"

namespace m350::ui {

void PanelContext::ask(const QString& question, std::function<void(bool)> answer) const {
    prompt_->ask(question, false, {}, [answer = std::move(answer)](std::optional<QString> value) {
        answer(value.has_value());
    });
}

void PanelContext::askText(const QString& question, const QString& initial,
                           std::function<void(std::optional<QString>)> answer) const {
    prompt_->ask(question, true, initial, std::move(answer));
}

void PanelContext::askSecret(const QString& question, std::function<void(std::optional<QString>)> answer) const {
    prompt_->ask(question, true, {}, std::move(answer), true);
}

} // namespace m350::ui
