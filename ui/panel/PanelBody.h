#pragma once

#include <QWidget>

namespace m350::ui {

// The window's body: the controller's screen and, where the window has room for both, the key
// panel with the handwheel to its right. On a window as small as the controller's own screen
// (800x480, the M350's LCD) the screen takes it whole and the key panel gives way (the keyboard is
// the panel's keys then), so the body's minimum is the screen's alone.
class PanelBody : public QWidget {
    Q_OBJECT
public:
    PanelBody(QWidget* screen, QWidget* keys, QWidget* parent = nullptr);
    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;
    bool keysShown() const;

    // From this window width on the key panel stands beside the screen.
    static constexpr int keysShownFrom = 960;

protected:
    bool event(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void place();

    QWidget* screen_;
    QWidget* keys_;
};

} // namespace m350::ui
