#pragma once

#include "ui/actions/OperatorAction.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>

#include <optional>
#include <vector>

namespace m350::ui {

class MainWindow;
class MachineSession;

// The longest virtual time a replay may reach: a day (three shifts). A later `t` is refused as it
// is read, naming its line: `{"t":1e9}` would otherwise keep the panel busy for weeks.
constexpr double kMostReplaySeconds = 24.0 * 3600.0;

// Where each action of a replay file stands: its line, and for a load the column of "load" (what
// playReplay's refusal points at); the line's first column for the others.
struct ReplayPlace {
    int line = 0;
    int column = 1;
};

// What is wrong with a line of a replay file, at its column (1-based).
struct ReplayLineProblem {
    int column = 1;
    QString why;
};

// One line of a replay (or attempt) file as a JSON object: nullopt for a blank or // line, and
// nullopt with `problem` filled when it is not one JSON object.
std::optional<QJsonObject> readReplayObject(const QByteArray& raw, ReplayLineProblem* problem);
// The action the object of line `raw` says, in time order after `previous` and within the longest
// replay; `column` as ReplayPlace has it (a problem's own column is in `problem`).
std::optional<OperatorAction> readReplayAction(const QJsonObject& object, const QByteArray& raw, double previous,
                                               ReplayLineProblem* problem, int* column);

// A replay file: JSON Lines, one operator action a line, in order of their virtual time `t`.
// Blank lines and lines starting with // are skipped. An error names file:line:column and what is
// wrong (a missing }, an unterminated string, an unknown action, a time out of order or too late).
std::optional<std::vector<OperatorAction>> readReplay(const QString& path, QString* error,
                                                      std::vector<ReplayPlace>* places = nullptr);

// When a replay lays the panel out. EachAction: after every action, as the live panel does.
// WhenRead: only before an action on the screen of a page that reads its layout (Page::readsLayout:
// the program editor, a machine view) and at the end. A page switch only changes the page keys
// reach; the stack shows the last one at the end. The end state and the screenshot are the same,
// the layout work a fraction.
enum class ReplayLayout { EachAction, WhenRead };

// Plays the actions against the panel in virtual time: time passes in display frames up to each
// action's `t`, then the action goes through the dispatcher. Ends at the last action's time. Time
// in which nothing happens passes at once (MachineSession::advanceWhileQuiet): the machine sees
// the same frames, the panel only the last. A `load` may open only a file the Program page shows
// on one of its disks (links followed): else the replay stops there. Empty when it played to its
// end, else why not, at `path`:line:column from `places` (readReplay's).
QString playReplay(MainWindow& window, MachineSession& session, const std::vector<OperatorAction>& actions,
                   const QString& path = {}, const std::vector<ReplayPlace>& places = {},
                   ReplayLayout layout = ReplayLayout::WhenRead);

// Why a replay may not play `action` (a `load` of a file the Program page does not show on one of
// its disks, links followed), at `path`:line:column of `place`; empty when it may.
QString refusedReplayLoad(MainWindow& window, const OperatorAction& action, const QString& path, const ReplayPlace& place);

// Lets the session catch up and the window show the latest snapshot (for screenshots and tests).
void settle(MachineSession& session);

} // namespace m350::ui
