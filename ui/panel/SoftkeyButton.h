#pragma once

#include <QHash>
#include <QPushButton>
#include <QSize>

namespace m350::ui {

// One softkey under the screen. Its label changes at every page switch and a push button measures
// its text again at each change (the shaping cost most of a page switch in a long replay): the
// sizes of the labels it has shown are kept, per label and enabled state, until its font or
// style changes.
class SoftkeyButton : public QPushButton {
    Q_OBJECT
public:
    explicit SoftkeyButton(QWidget* parent = nullptr) : QPushButton(parent) {}
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void changeEvent(QEvent* event) override;

private:
    struct Sizes {
        QSize hint;
        QSize minimum;
    };
    const Sizes& sizes() const;

    mutable QHash<QString, Sizes> sizes_;
};

} // namespace m350::ui
