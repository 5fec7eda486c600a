#pragma once

#include "ui/i18n/PanelText.h"
#include "ui/session/PanelSnapshot.h"

namespace m350::ui {

// The status line's mode and state fields, read off a snapshot as the M350 shows them.
// On the MDI and Probe pages an idle panel is in that page's mode, as the M350 shows it.
PanelText::Mode displayedMode(const PanelSnapshot& snapshot, const QString& page = {});
PanelText::State displayedState(const PanelSnapshot& snapshot);

} // namespace m350::ui
