#include "ui/panel/PanelBody.h"

#include <QEvent>

namespace m350::ui {

namespace {

constexpr int margin = 2;
constexpr int spacing = 4;

} // namespace

PanelBody::PanelBody(QWidget* screen, QWidget* keys, QWidget* parent)
    : QWidget(parent), screen_(screen), keys_(keys) {
    screen_->setParent(this);
    keys_->setParent(this);
}

QSize PanelBody::minimumSizeHint() const {
    return screen_->minimumSizeHint().grownBy({margin, margin, margin, margin});
}

// The size of the M350's screen (1024x600). A constant: the window is always given its
// size (1024x600 or --size), so the hint only names the size the panel is drawn for; measuring
// the page shown for it (its wrapped texts laid out at a width nobody uses) cost a tenth of
// every page switch.
QSize PanelBody::sizeHint() const { return {1024, 600}; }

bool PanelBody::keysShown() const { return !keys_->isHidden(); }

// The children have no layout to tell: a page that needs more room asks the body again.
bool PanelBody::event(QEvent* event) {
    if (event->type() == QEvent::LayoutRequest) {
        updateGeometry();
        place();
    }
    return QWidget::event(event);
}

void PanelBody::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    place();
}

void PanelBody::place() {
    const QRect area = rect().marginsRemoved({margin, margin, margin, margin});
    const int keysWidth = keys_->minimumWidth();
    const bool room = width() >= keysShownFrom &&
                      area.width() - spacing - keysWidth >= screen_->minimumSizeHint().width() &&
                      area.height() >= keys_->minimumSizeHint().height();
    keys_->setVisible(room);
    if (room) {
        screen_->setGeometry(area.x(), area.y(), area.width() - spacing - keysWidth, area.height());
        keys_->setGeometry(area.right() + 1 - keysWidth, area.y(), keysWidth, area.height());
    } else {
        screen_->setGeometry(area);
    }
}

} // namespace m350::ui
