#pragma once

#include "ui/actions/OperatorAction.h"

#include <optional>

class QKeyEvent;

namespace m350::ui {

// The PC keyboard as the panel's keys (README, "Keys and the handwheel"): each key's chords are
// in its PanelKey row (`keyboard`), the one table of them; only two things are not a key of that
// table: Shift+F1-F6 press the second softkey row (softkeys 7-12), and Alt+Left/Right turn the
// handwheel one detent (the returned wheel action has axis -1: the handwheel's own axis and step
// apply). F12 is E-STOP on every page. Jog keys give a press and a release.
std::optional<OperatorAction> actionForKey(const QKeyEvent& event, bool pressed);

} // namespace m350::ui
