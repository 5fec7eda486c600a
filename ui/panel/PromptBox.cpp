#include "ui/panel/PromptBox.h"

#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

namespace m350::ui {

PromptBox::PromptBox(QWidget* parent) : QDialog(parent) {
    setObjectName("promptBox");
    setModal(true);
    setWindowTitle(QStringLiteral("M350"));
    auto* layout = new QVBoxLayout(this);
    question_ = new QLabel(this);
    question_->setObjectName("promptQuestion");
    question_->setWordWrap(true);
    edit_ = new QLineEdit(this);
    edit_->setObjectName("promptText");
    hint_ = new QLabel(this);
    hint_->setObjectName("promptHint");
    layout->addWidget(question_);
    layout->addWidget(edit_);
    layout->addWidget(hint_);
    setMinimumWidth(420);
}

void PromptBox::ask(const QString& question, bool withText, const QString& initial, Answer answer, bool secret) {
    if (answer_) {
        finishWith(std::nullopt); // a newer question replaces an unanswered one
    }
    question_->setText(question);
    edit_->setVisible(withText);
    edit_->setEchoMode(secret ? QLineEdit::Password : QLineEdit::Normal);
    edit_->setText(initial);
    hint_->setText(tr("[Enter] OK    [Esc] Cancel"));
    answer_ = std::move(answer);
    open();
}

QString PromptBox::question() const { return question_->text(); }
QString PromptBox::textValue() const { return edit_->text(); }
bool PromptBox::secret() const { return edit_->echoMode() == QLineEdit::Password; }

void PromptBox::type(const QString& text) {
    if (edit_->isVisible()) {
        edit_->insert(text);
    }
}

void PromptBox::backspace() { edit_->backspace(); }

void PromptBox::confirm() { finishWith(edit_->isVisible() ? edit_->text() : QString()); }
void PromptBox::cancel() { finishWith(std::nullopt); }

void PromptBox::finishWith(std::optional<QString> value) {
    Answer answer = std::move(answer_);
    answer_ = nullptr;
    hide();
    if (answer) {
        answer(value);
    }
}

// Keys reach the prompt through the dispatcher; these only keep QDialog's own defaults from
// closing the box behind the dispatcher's back.
void PromptBox::keyPressEvent(QKeyEvent* event) { event->ignore(); }

} // namespace m350::ui
