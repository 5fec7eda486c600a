#pragma once

#include "ui/i18n/PanelText.h"
#include "ui/session/PanelSnapshot.h"

namespace m350::ui {

// The status line's mode and state fields, read off a snapshot as the M350 shows them.
PanelText::Mode displayedMode(const PanelSnapshot& snapshot);
PanelText::State displayedState(const PanelSnapshot& snapshot);

} // namespace m350::ui
