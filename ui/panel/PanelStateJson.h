#pragma once

#include "ui/session/PanelSnapshot.h"

#include <QJsonObject>

namespace m350::ui {

// The machine part of `m350-hmi --state`: mode and state (untranslated keys), positions, tool,
// the #1503 message, the alarm, input and output levels (the window adds page, prompt and MDI lines).
QJsonObject panelStateJson(const PanelSnapshot& snapshot);

} // namespace m350::ui
