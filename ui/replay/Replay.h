#pragma once

#include "ui/actions/OperatorAction.h"

#include <QString>

#include <optional>
#include <vector>

namespace m350::ui {

class MainWindow;
class MachineSession;

// A replay file: JSON Lines, one operator action a line, in order of their virtual time `t`.
// Blank lines and lines starting with // are skipped. An error names the file and line.
std::optional<std::vector<OperatorAction>> readReplay(const QString& path, QString* error);

// Plays the actions against the panel in virtual time: time passes in display frames up to each
// action's `t`, then the action goes through the dispatcher. Ends at the last action's time.
void playReplay(MainWindow& window, MachineSession& session, const std::vector<OperatorAction>& actions);

// Lets the session catch up and the window show the latest snapshot (for screenshots and tests).
void settle(MachineSession& session);

} // namespace m350::ui
