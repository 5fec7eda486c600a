#pragma once

#include "ui/pages/Page.h"

#include <QVector>
#include <QWidget>

class QPushButton;

namespace m350::ui {

// The F1-F6 softkeys under the screen: one row, or two where the page has twelve (the second
// row, labelled ⇧F1-⇧F6, answers SHIFT with F1-F6). A click is the same action as the key.
class SoftkeyBar : public QWidget {
    Q_OBJECT
public:
    explicit SoftkeyBar(QWidget* parent = nullptr);
    void show(const QVector<Page::Softkey>& keys);
    QString label(int number) const; // 1-12
    bool enabled(int number) const;

signals:
    void pressed(int number);

private:
    QVector<QPushButton*> buttons_;
};

} // namespace m350::ui
