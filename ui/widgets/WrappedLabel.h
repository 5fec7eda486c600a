#pragma once

#include "ui/widgets/MeasuredLabel.h"

namespace m350::ui {

// A word-wrapped label (a page's help, the MDI result, the alarm line). A layout asks a wrapped
// label its height for a width each time it is laid out, and QLabel lays its text out again for
// every question: MeasuredLabel keeps the answers.
class WrappedLabel : public MeasuredLabel {
    Q_OBJECT
public:
    explicit WrappedLabel(QWidget* parent = nullptr);
};

} // namespace m350::ui
