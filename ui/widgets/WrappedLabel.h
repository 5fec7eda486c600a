#pragma once

#include <QLabel>

#include <utility>
#include <vector>

namespace m350::ui {

// A word-wrapped label (a page's help, the MDI result, the alarm line). A layout asks a wrapped
// label its height for a width each time it is laid out, and QLabel lays its text out again for
// every question: the panel asked it at each page switch for the same text at the same widths.
// The answers are kept for the label's text until the text, its font or its style change.
class WrappedLabel : public QLabel {
    Q_OBJECT
public:
    explicit WrappedLabel(QWidget* parent = nullptr);
    int heightForWidth(int width) const override;

protected:
    void changeEvent(QEvent* event) override;

private:
    mutable QString measuredText_;
    mutable std::vector<std::pair<int, int>> heights_; // (width, height) for measuredText_
};

} // namespace m350::ui
