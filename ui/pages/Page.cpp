#include "ui/pages/Page.h"

#include <QEvent>

namespace m350::ui {

void Page::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        emit softkeysChanged();
    }
    QWidget::changeEvent(event);
}

} // namespace m350::ui
