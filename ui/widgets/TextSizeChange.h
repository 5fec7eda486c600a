#pragma once

#include <QEvent>

namespace m350::ui {

// Whether a widget's change event may change how large the same text is drawn (its font, its
// style sheet, its margins): a kept text measurement is stale after one.
inline bool changesTextSize(const QEvent* event) {
    const QEvent::Type type = event->type();
    return type == QEvent::FontChange || type == QEvent::StyleChange || type == QEvent::ContentsRectChange;
}

} // namespace m350::ui
