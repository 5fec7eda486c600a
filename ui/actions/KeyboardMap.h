#pragma once

#include "ui/actions/OperatorAction.h"

#include <optional>

class QKeyEvent;

namespace m350::ui {

// The PC keyboard as the panel's keys (README, "Keyboard"): F1-F6 softkeys (Shift for the second
// row), Enter, Esc, arrows, typed text; F9 START, F10 PAUSE, F11 RESET, F12 E-stop; Ctrl+arrows
// and Ctrl+PgUp/PgDn jog X Y Z while held; Alt+Left/Right turn the handwheel one detent (the
// returned wheel action has axis -1: the handwheel's own axis and step apply).
std::optional<OperatorAction> actionForKey(const QKeyEvent& event, bool pressed);

} // namespace m350::ui
