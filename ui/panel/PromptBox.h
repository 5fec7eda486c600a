#pragma once

#include "ui/pages/PanelPrompt.h"

#include <QDialog>

class QLabel;
class QLineEdit;

namespace m350::ui {

// The panel's own question box (是否进行开机寻零操作?, 请输入固定对刀的刀具号:) and the macro's
// #1505 dialog: modal over the panel, answered with Enter or Esc, with a line of typed text when
// it asks for a value. It never blocks the event loop (open(), not exec()).
class PromptBox : public QDialog, public PanelPrompt {
    Q_OBJECT
public:
    explicit PromptBox(QWidget* parent);

    void ask(const QString& question, bool withText, const QString& initial, Answer answer,
             bool secret = false) override;
    bool active() const override { return isVisible(); }
    QString question() const;
    QString textValue() const;
    bool secret() const; // the text shows as dots
    void type(const QString& text) override;
    void backspace() override;
    void confirm() override;
    void cancel() override;

protected:
    void keyPressEvent(QKeyEvent* event) override;

private:
    void finishWith(std::optional<QString> value);
    QLabel* question_;
    QLineEdit* edit_;
    QLabel* hint_;
    Answer answer_;
};

} // namespace m350::ui
