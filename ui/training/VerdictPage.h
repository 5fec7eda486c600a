#pragma once

#include "core/training/Verdict.h"

#include <QWidget>

class QLabel;
class QTableWidget;

namespace m350::ui {

// The verdict of a handed-in attempt: passed or failed, the score and the time, then each check
// with what was measured, what was expected and, when it failed, why. The selected failed check's
// parameter, tool or macro line is what "open" shows in the panel.
class VerdictPage : public QWidget {
    Q_OBJECT
public:
    explicit VerdictPage(QWidget* parent = nullptr);
    void show(const training::Verdict& verdict, const QString& title, MessageLanguage language);
    int selected() const;
    void move(int by);
    // The selected check's target (CheckTarget::Kind::None when it points at nothing).
    training::CheckTarget target() const;
    QString summary() const;
    QTableWidget* table() const { return table_; }

private:
    QLabel* summary_;
    QTableWidget* table_;
    QLabel* reason_;
    std::vector<training::CheckResult> checks_;
    MessageLanguage language_ = MessageLanguage::Chinese;
    void showReason();
};

} // namespace m350::ui
