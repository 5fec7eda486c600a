#include "ui/replay/DeferredLayout.h"

#include <QCoreApplication>
#include <QEvent>

namespace m350::ui {

DeferredLayout::DeferredLayout(QObject* parent) : QObject(parent) { QCoreApplication::instance()->installEventFilter(this); }

DeferredLayout::~DeferredLayout() {
    QCoreApplication::instance()->removeEventFilter(this);
    catchUp();
}

void DeferredLayout::catchUp() {
    if (held_.empty()) {
        return;
    }
    passing_ = true;
    for (const QPointer<QObject>& widget : held_) {
        if (widget) {
            QCoreApplication::postEvent(widget, new QEvent(QEvent::LayoutRequest));
        }
    }
    held_.clear();
    heldSet_.clear();
    // a layout that runs may ask its parent's again: those run in this same pass
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    passing_ = false;
}

bool DeferredLayout::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::LayoutRequest || passing_ || !watched->isWidgetType()) {
        return false;
    }
    if (!heldSet_.contains(watched)) {
        heldSet_.insert(watched);
        held_.emplace_back(watched);
    }
    return true;
}

} // namespace m350::ui
