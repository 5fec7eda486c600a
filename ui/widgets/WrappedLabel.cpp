#include "ui/widgets/WrappedLabel.h"

#include "ui/widgets/TextSizeChange.h"

namespace m350::ui {

namespace {

constexpr std::size_t kMostWidthsKept = 8; // the widths one layout pass asks are few

} // namespace

WrappedLabel::WrappedLabel(QWidget* parent) : QLabel(parent) { setWordWrap(true); }

int WrappedLabel::heightForWidth(int width) const {
    if (text() != measuredText_) {
        measuredText_ = text();
        heights_.clear();
    }
    for (const auto& [measured, height] : heights_) {
        if (measured == width) {
            return height;
        }
    }
    const int height = QLabel::heightForWidth(width);
    if (heights_.size() >= kMostWidthsKept) {
        heights_.erase(heights_.begin());
    }
    heights_.emplace_back(width, height);
    return height;
}

void WrappedLabel::changeEvent(QEvent* event) {
    if (changesTextSize(event)) {
        heights_.clear();
    }
    QLabel::changeEvent(event);
}

} // namespace m350::ui
