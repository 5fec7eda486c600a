#include "ui/panel/PageStack.h"

namespace m350::ui {

// A stacked layout measured by its current page alone.
class PageStack::ShownPageLayout : public QStackedLayout {
public:
    using QStackedLayout::QStackedLayout;
    QSize sizeHint() const override { return shown() ? shown()->sizeHint() : QStackedLayout::sizeHint(); }
    QSize minimumSize() const override { return shown() ? shownMinimum() : QStackedLayout::minimumSize(); }
    bool hasHeightForWidth() const override {
        return shown() ? shown()->hasHeightForWidth() : QStackedLayout::hasHeightForWidth();
    }
    int heightForWidth(int width) const override {
        return shown() ? shown()->heightForWidth(width) : QStackedLayout::heightForWidth(width);
    }

private:
    QWidget* shown() const { return currentWidget(); }
    QSize shownMinimum() const { return shown()->minimumSizeHint().expandedTo(shown()->minimumSize()); }
};

PageStack::PageStack(QWidget* parent) : QWidget(parent), layout_(new ShownPageLayout(this)) {
    connect(layout_, &QStackedLayout::currentChanged, this, [this] { updateGeometry(); });
}

void PageStack::addWidget(QWidget* page) { layout_->addWidget(page); }
void PageStack::setCurrentWidget(QWidget* page) { layout_->setCurrentWidget(page); }
QWidget* PageStack::currentWidget() const { return layout_->currentWidget(); }

QSize PageStack::minimumSizeHint() const {
    const QWidget* page = currentWidget();
    return page ? page->minimumSizeHint().expandedTo(page->minimumSize()) : QWidget::minimumSizeHint();
}

} // namespace m350::ui
