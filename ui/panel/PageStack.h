#pragma once

#include <QStackedWidget>

namespace m350::ui {

// The screen's pages, one shown at a time: it needs the room of the page it shows, not of the
// largest page (a page never shown is measured before its texts wrap to the screen's width).
class PageStack : public QStackedWidget {
    Q_OBJECT
public:
    explicit PageStack(QWidget* parent = nullptr);
    QSize minimumSizeHint() const override;
};

} // namespace m350::ui
