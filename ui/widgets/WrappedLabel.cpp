#include "ui/widgets/WrappedLabel.h"

namespace m350::ui {

WrappedLabel::WrappedLabel(QWidget* parent) : MeasuredLabel(parent) { setWordWrap(true); }

} // namespace m350::ui
