#include "ui/panel/PromptBox.h"
#include "ui/widgets/MeasuredLabel.h"
#include "ui/widgets/WrappedLabel.h"

#include <QFrame>
#include <QGridLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

#include <algorithm>

namespace m350::ui {

PromptBox::PromptBox(QWidget* parent) : QWidget(parent) {
    setObjectName("promptBox");
    setAttribute(Qt::WA_StyledBackground); // the dimmed backdrop of panel.qss
    auto* centre = new QGridLayout(this);
    frame_ = new QFrame(this);
    frame_->setObjectName("promptFrame");
    centre->addWidget(frame_, 0, 0, Qt::AlignCenter);
    auto* layout = new QVBoxLayout(frame_);
    question_ = new WrappedLabel(frame_);
    question_->setObjectName("promptQuestion");
    edit_ = new QLineEdit(frame_);
    edit_->setObjectName("promptText");
    hint_ = new MeasuredLabel(frame_);
    hint_->setObjectName("promptHint");
    layout->addWidget(question_);
    layout->addWidget(edit_);
    layout->addWidget(hint_);
    frame_->setMinimumWidth(420);
    hide();
    parent->installEventFilter(this); // follows the window's size
}

bool PromptBox::eventFilter(QObject* watched, QEvent* event) {
    if (watched == parentWidget() && event->type() == QEvent::Resize) {
        setGeometry(parentWidget()->rect());
    }
    return QWidget::eventFilter(watched, event);
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
    frame_->setMaximumWidth(std::max(420, parentWidget()->width() * 3 / 4));
    setGeometry(parentWidget()->rect());
    raise();
    show();
    edit_->setFocus();
}

QString PromptBox::question() const { return question_->text(); }
QString PromptBox::textValue() const { return edit_->text(); }
bool PromptBox::secret() const { return edit_->echoMode() == QLineEdit::Password; }

void PromptBox::type(const QString& text) {
    if (!edit_->isHidden()) {
        edit_->insert(text);
    }
}

void PromptBox::backspace() { edit_->backspace(); }

void PromptBox::confirm() { finishWith(!edit_->isHidden() ? edit_->text() : QString()); }
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
