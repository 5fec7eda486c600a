#pragma once

#include <QStackedLayout>
#include <QWidget>

namespace m350::ui {

// The screen's pages, one shown at a time: it needs the room of the page it shows, not of the
// largest page (a page never shown is measured before its texts wrap to the screen's width).
// Qt's QStackedWidget asks every page for its size and its height for a width each time the
// screen is laid out (any label that changes text), which measured the wrapped texts of all 16
// pages: this stack asks the shown page only.
class PageStack : public QWidget {
    Q_OBJECT
public:
    explicit PageStack(QWidget* parent = nullptr);
    void addWidget(QWidget* page);
    void setCurrentWidget(QWidget* page);
    QWidget* currentWidget() const;
    QSize minimumSizeHint() const override;

private:
    class ShownPageLayout;
    ShownPageLayout* layout_;
};

} // namespace m350::ui
