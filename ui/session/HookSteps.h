#pragma once

#include "ui/session/MachineSession.h"

#include <QVector>

#include <optional>

namespace m350::ui {

// The panel's keys that have a hook file, as steps for MachineSession::runHooks: the hook, and
// the built-in MDI lines that run when the machine folder has none.

// 回工件原点 of every axis in `axes` (gotozero.nc): Z up to the safe height (param 69) first, the
// others over, Z down last.
MachineSession::HookStep goToWorkZeroStep(const QVector<int>& axes);
// The M-code keys M3 M4 M5 M8 M9 M10 M11 M19 (M3.nc ...): the code as an MDI line. nullopt for
// another code.
std::optional<MachineSession::HookStep> mCodeKeyStep(int code);

} // namespace m350::ui
