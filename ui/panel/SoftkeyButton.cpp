#include "ui/panel/SoftkeyButton.h"

#include "ui/widgets/TextSizeChange.h"

namespace m350::ui {

namespace {

constexpr int kMostLabelsKept = 512; // every page's menus in both languages, and more

} // namespace

const SoftkeyButton::Sizes& SoftkeyButton::sizes() const {
    // a disabled key may be drawn with other margins by a style sheet: its own entry
    const QString key = isEnabled() ? text() : QLatin1Char('\0') + text();
    auto found = sizes_.constFind(key);
    if (found == sizes_.cend()) {
        if (sizes_.size() >= kMostLabelsKept) {
            sizes_.clear();
        }
        auto added = sizes_.insert(key, {QPushButton::sizeHint(), {}});
        added->minimum = QPushButton::minimumSizeHint(); // may ask sizeHint(): found above now
        return *added;
    }
    return *found;
}

QSize SoftkeyButton::sizeHint() const { return sizes().hint; }
QSize SoftkeyButton::minimumSizeHint() const { return sizes().minimum; }

void SoftkeyButton::changeEvent(QEvent* event) {
    if (changesTextSize(event)) {
        sizes_.clear();
    }
    QPushButton::changeEvent(event);
}

} // namespace m350::ui
