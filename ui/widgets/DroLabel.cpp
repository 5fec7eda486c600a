#include "ui/widgets/DroLabel.h"

#include <QFontMetrics>
#include <QResizeEvent>

#include <algorithm>

namespace m350::ui {

namespace {

constexpr int kSmallestPoint = 7;
constexpr int kLargestPoint = 60;
constexpr int kPreferredPoint = 22; // what the 1024x600 panel shows
constexpr int kPreferredWindowHeight = 600;
constexpr int kSlack = 4; // px: a glyph's overhang past its advance (the sign, the last digit)

} // namespace

DroLabel::DroLabel(QWidget* parent) : QLabel(parent) {
    // wants the 22 pt width, takes any width down to the 7 pt one's
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    QFont f = font();
    f.setPointSize(kPreferredPoint);
    setFont(f);
}

QString DroLabel::widestText() {
    return QStringLiteral("-99999.999");
}

QSize DroLabel::minimumSizeHint() const {
    QFont f = font();
    f.setPointSize(kSmallestPoint);
    const QFontMetrics metrics(f);
    const QMargins m = contentsMargins();
    return {metrics.horizontalAdvance(widestText()) + m.left() + m.right() + 2 * margin(),
            metrics.height() + m.top() + m.bottom() + 2 * margin()};
}

QSize DroLabel::sizeHint() const {
    QFont f = font();
    f.setPointSize(kPreferredPoint);
    const QMargins m = contentsMargins();
    return {QFontMetrics(f).horizontalAdvance(widestText()) + m.left() + m.right() + 2 * margin(),
            fontMetrics().height() + m.top() + m.bottom() + 2 * margin()}; // as tall as the font it has
}

void DroLabel::resizeEvent(QResizeEvent* event) {
    QLabel::resizeEvent(event);
    fitFont();
}

void DroLabel::fitFont() {
    const QRect room = contentsRect().marginsRemoved(QMargins(margin(), margin(), margin(), margin()));
    // The window's height sets how large the digits grow (22 pt at 600 px, as the panel was drawn);
    // the label's width how large they may be.
    const int tallest = std::clamp(window()->height() * kPreferredPoint / kPreferredWindowHeight, kSmallestPoint,
                                   kLargestPoint);
    QFont f = font();
    int point = kSmallestPoint;
    for (int p = tallest; p > kSmallestPoint; --p) {
        f.setPointSize(p);
        if (QFontMetrics(f).horizontalAdvance(widestText()) + kSlack <= room.width()) {
            point = p;
            break;
        }
    }
    if (font().pointSize() != point) {
        f.setPointSize(point);
        setFont(f);
    }
}

} // namespace m350::ui
