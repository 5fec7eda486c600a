#include "ui/widgets/MeasuredLabel.h"

#include "ui/widgets/TextSizeChange.h"

namespace m350::ui {

namespace {

constexpr std::size_t kMostTextsKept = 64;  // a list's rows looked at back and forth
constexpr std::size_t kMostWidthsKept = 8; // the widths one layout pass asks are few
constexpr QSize kNotMeasured{-1, -1};

} // namespace

MeasuredLabel::MeasuredLabel(QWidget* parent) : QLabel(parent) {}
MeasuredLabel::MeasuredLabel(const QString& text, QWidget* parent) : QLabel(text, parent) {}

MeasuredLabel::Shape MeasuredLabel::shape() const {
    return {text(), static_cast<int>(textFormat()), static_cast<int>(alignment()), wordWrap(), indent(), margin(),
            maximumWidth()};
}

MeasuredLabel::Measures& MeasuredLabel::measures() const {
    Shape now = shape();
    for (auto it = kept_.begin(); it != kept_.end(); ++it) {
        if (it->shape == now) {
            if (it != kept_.begin()) {
                kept_.splice(kept_.begin(), kept_, it);
            }
            return kept_.front();
        }
    }
    if (kept_.size() >= kMostTextsKept) {
        kept_.pop_back();
    }
    kept_.push_front({std::move(now), kNotMeasured, kNotMeasured, {}});
    return kept_.front();
}

QSize MeasuredLabel::sizeHint() const {
    Measures& m = measures();
    if (m.size == kNotMeasured) {
        m.size = QLabel::sizeHint();
    }
    return m.size;
}

QSize MeasuredLabel::minimumSizeHint() const {
    Measures& m = measures();
    if (m.least == kNotMeasured) {
        m.least = QLabel::minimumSizeHint();
    }
    return m.least;
}

int MeasuredLabel::heightForWidth(int width) const {
    Measures& m = measures();
    for (const auto& [measured, height] : m.heights) {
        if (measured == width) {
            return height;
        }
    }
    const int height = QLabel::heightForWidth(width);
    if (m.heights.size() >= kMostWidthsKept) {
        m.heights.erase(m.heights.begin());
    }
    m.heights.emplace_back(width, height);
    return height;
}

void MeasuredLabel::changeEvent(QEvent* event) {
    if (changesTextSize(event)) {
        kept_.clear();
    }
    QLabel::changeEvent(event);
}

} // namespace m350::ui
