#pragma once

#include "ui/pages/PanelPrompt.h"

#include <QWidget>

class QFrame;
class QLabel;
class QLineEdit;

namespace m350::ui {

// The panel's own question box (是否进行开机寻零操作?, 请输入固定对刀的刀具号:) and the macro's
// #1505 dialog, answered with Enter or Esc, with a line of typed text when it asks for a value.
// It is drawn inside the panel's window, as the controller's screen shows it: an overlay over the
// whole window (it takes the mouse from what lies under it) with the box in its middle, so a grab
// of the window (m350-hmi --screenshot) shows it. It never blocks the event loop.
class PromptBox : public QWidget, public PanelPrompt {
    Q_OBJECT
public:
    explicit PromptBox(QWidget* parent);

    void ask(const QString& question, bool withText, const QString& initial, Answer answer,
             bool secret = false) override;
    bool active() const override { return !isHidden(); } // shown, also in a window not on screen
    QString question() const;
    QString textValue() const;
    bool secret() const; // the text shows as dots
    void type(const QString& text) override;
    void backspace() override;
    void confirm() override;
    void cancel() override;

protected:
    void keyPressEvent(QKeyEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void finishWith(std::optional<QString> value);
    QFrame* frame_;
    QLabel* question_;
    QLineEdit* edit_;
    QLabel* hint_;
    Answer answer_;
};

} // namespace m350::ui
