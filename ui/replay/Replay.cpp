#include "ui/replay/Replay.h"

#include "ui/actions/PanelKey.h"
#include "ui/pages/PageId.h"
#include "ui/pages/ProgramPage.h"
#include "ui/panel/MainWindow.h"
#include "ui/replay/DeferredLayout.h"
#include "ui/session/MachineSession.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonParseError>

namespace m350::ui {

namespace {

// What is wrong with a line QJsonDocument would not read, said as the writer sees it: Qt calls a
// missing } at the end "unterminated string". Column 1-based; nullopt: ask Qt.
std::optional<std::pair<int, QString>> shapeProblem(const QByteArray& line) {
    if (!line.startsWith('{')) {
        return std::pair{1, QCoreApplication::translate("m350::ui::Replay", "a line holds one action, a JSON object {...}")};
    }
    std::vector<std::pair<char, int>> open; // bracket, column
    int stringAt = 0;
    for (int i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (stringAt > 0) {
            if (c == '\\') {
                ++i;
            } else if (c == '"') {
                stringAt = 0;
            }
            continue;
        }
        if (c == '"') {
            stringAt = i + 1;
        } else if (c == '{' || c == '[') {
            open.emplace_back(c, i + 1);
        } else if (c == '}' || c == ']') {
            const char expected = c == '}' ? '{' : '[';
            if (open.empty() || open.back().first != expected) {
                return std::pair{i + 1, QCoreApplication::translate("m350::ui::Replay", "'%1' closes nothing that is open").arg(QLatin1Char(c))};
            }
            open.pop_back();
            if (open.empty() && i + 1 < line.size()) {
                return std::pair{i + 2, QCoreApplication::translate("m350::ui::Replay", "text after the action's closing }: one action a line")};
            }
        }
    }
    if (stringAt > 0) {
        return std::pair{stringAt, QCoreApplication::translate("m350::ui::Replay", "unterminated string: the \" opened here is not closed on this line")};
    }
    if (!open.empty()) {
        return std::pair{static_cast<int>(line.size()) + 1,
                         QCoreApplication::translate("m350::ui::Replay", "missing '%1' at the end of the line (the '%2' at column %3 is not closed)")
                             .arg(QLatin1Char(open.back().first == '{' ? '}' : ']'))
                             .arg(QLatin1Char(open.back().first))
                             .arg(open.back().second)};
    }
    return std::nullopt;
}

// The column of "name" as a key of the line (1 when it is not found as written).
int keyColumn(const QByteArray& line, const QString& name) {
    const qsizetype at = line.indexOf('"' + name.toUtf8() + '"');
    return at < 0 ? 1 : static_cast<int>(at) + 1;
}

// The action's own key on its line: what its messages point at.
QString actionKey(const QJsonObject& object) {
    for (const QString& key : object.keys()) {
        if (key != QLatin1String("t")) {
            return key;
        }
    }
    return QStringLiteral("t");
}

// Whether the Program page lists `file` on one of its disks (a link counts where it leads), and
// the disks' folders for the message.
bool onProgramDisk(MainWindow& window, const QString& file, QStringList* disks) {
    auto* programs = dynamic_cast<ProgramPage*>(window.page(PageId::program));
    if (!programs) {
        return false;
    }
    const QFileInfo target(QFileInfo(file).canonicalFilePath());
    bool shown = false;
    for (ProgramFiles::Disk disk : {ProgramFiles::Disk::Local, ProgramFiles::Disk::User, ProgramFiles::Disk::System}) {
        const QString folder = programs->folderOf(disk);
        disks->append(folder);
        if (target.filePath().isEmpty() || target.absolutePath() != QFileInfo(folder).canonicalFilePath()) {
            continue;
        }
        for (const ProgramFiles::Entry& entry : ProgramFiles::list(folder, disk, ProgramFiles::Sort::Name)) {
            shown = shown || entry.name == target.fileName();
        }
    }
    return shown;
}

// The role of the panel key the action presses (a key, a key down or up of a known key), else none.
std::optional<PanelKey::Role> keyRole(const OperatorAction& action) {
    using Kind = OperatorAction::Kind;
    if (action.kind != Kind::Key && action.kind != Kind::KeyDown && action.kind != Kind::KeyUp) {
        return std::nullopt;
    }
    const PanelKey* key = PanelKey::named(action.name);
    return key ? std::optional(key->role) : std::nullopt;
}

// Whether the action goes to the machine alone: the machine's own keys (cycle, jog, overrides, the
// handwheel's switches), the wheel, a forced input, a load. Each ends in a snapshot of its own.
bool goesToMachineAlone(const OperatorAction& action) {
    using Kind = OperatorAction::Kind;
    using Role = PanelKey::Role;
    const std::optional<Role> role = keyRole(action);
    return action.kind == Kind::Wheel || action.kind == Kind::Force || action.kind == Kind::Load ||
           role == Role::Machine || role == Role::Jog || role == Role::Wheel;
}

// Whether the action may read what the page shows: a softkey, a key for the page or a question
// (a cursor key moving a list, ENTER), typed text, the language. A page switch renders the page
// it opens; the machine alone and time passing read nothing of the screen.
bool readsScreen(const OperatorAction& action) {
    using Kind = OperatorAction::Kind;
    return action.kind != Kind::Wait && action.kind != Kind::Page && !goesToMachineAlone(action) &&
           keyRole(action) != PanelKey::Role::Page;
}

// The session's queued calls run and their snapshots delivered (twice: a snapshot's render may post more).
template <class Deliver> void settleWith(MachineSession& session, Deliver deliver) {
    session.sync();
    deliver();
    deliver();
}

} // namespace

std::optional<QJsonObject> readReplayObject(const QByteArray& raw, ReplayLineProblem* problem) {
    const QByteArray line = raw.trimmed();
    problem->why.clear();
    if (line.isEmpty() || line.startsWith("//")) {
        return std::nullopt;
    }
    const int indent = static_cast<int>(raw.indexOf(line.at(0))); // columns count from the raw line
    QJsonParseError parse{};
    QJsonDocument doc = QJsonDocument::fromJson(line, &parse);
    if (parse.error != QJsonParseError::NoError || !doc.isObject()) {
        if (auto shape = shapeProblem(line)) {
            *problem = {indent + shape->first, shape->second};
        } else {
            *problem = {indent + parse.offset + 1,
                        parse.error != QJsonParseError::NoError ? parse.errorString() : QCoreApplication::translate("m350::ui::Replay", "expected {...}")};
        }
        return std::nullopt;
    }
    return doc.object();
}

std::optional<OperatorAction> readReplayAction(const QJsonObject& object, const QByteArray& raw, double previous,
                                               ReplayLineProblem* problem, int* column) {
    const QByteArray line = raw.trimmed();
    const int indent = line.isEmpty() ? 0 : static_cast<int>(raw.indexOf(line.at(0)));
    QString why;
    auto action = OperatorAction::fromJson(object, &why);
    if (!action) {
        const QString key = why.startsWith(QLatin1String("\"t\"")) ? QStringLiteral("t") : actionKey(object);
        *column = indent + keyColumn(line, key);
        *problem = {*column, why};
        return std::nullopt;
    }
    // the action's column is for the messages of a load refused as the replay plays; the others
    // start at the line's first column (a replay reads a million lines: no key looked for twice)
    *column = action->kind == OperatorAction::Kind::Load ? indent + keyColumn(line, QStringLiteral("load")) : indent + 1;
    const auto timeColumn = [&] { return indent + keyColumn(line, QStringLiteral("t")); };
    if (!(action->t <= kMostReplaySeconds)) {
        *problem = {timeColumn(), QCoreApplication::translate("m350::ui::Replay", "t = %1 s is beyond the longest replay, %2 s (24 h) of virtual time")
                                    .arg(action->t)
                                    .arg(kMostReplaySeconds)};
        return std::nullopt;
    }
    if (action->t < previous) {
        *problem = {timeColumn(), QCoreApplication::translate("m350::ui::Replay", "t = %1 comes before the previous action's %2 (actions must be in "
                                               "time order)")
                                    .arg(action->t)
                                    .arg(previous)};
        return std::nullopt;
    }
    return action;
}

std::optional<std::vector<OperatorAction>> readReplay(const QString& path, QString* error,
                                                      std::vector<ReplayPlace>* places) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        *error = QCoreApplication::translate("m350::ui::Replay", "%1: cannot read: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    std::vector<OperatorAction> actions;
    int lineNumber = 0;
    double previous = 0.0;
    ReplayLineProblem problem;
    auto failAt = [&] {
        *error = QStringLiteral("%1:%2:%3: %4").arg(path).arg(lineNumber).arg(problem.column).arg(problem.why);
        return std::nullopt;
    };
    while (!file.atEnd()) {
        ++lineNumber;
        const QByteArray raw = file.readLine();
        const std::optional<QJsonObject> object = readReplayObject(raw, &problem);
        if (!object) {
            if (!problem.why.isEmpty()) {
                return failAt();
            }
            continue;
        }
        int column = 1;
        auto action = readReplayAction(*object, raw, previous, &problem, &column);
        if (!action) {
            return failAt();
        }
        previous = action->t;
        actions.push_back(*action);
        if (places) {
            places->push_back({lineNumber, column});
        }
    }
    return actions;
}

QString refusedReplayLoad(MainWindow& window, const OperatorAction& action, const QString& path, const ReplayPlace& place) {
    QStringList disks;
    if (action.kind != OperatorAction::Kind::Load || onProgramDisk(window, action.name, &disks)) {
        return {};
    }
    return QCoreApplication::translate("m350::ui::Replay", "%1:%2:%3: load \"%4\": a replay loads only a program the Program page shows on "
                          "its disks (%5), links followed: refused")
        .arg(path)
        .arg(place.line)
        .arg(place.column)
        .arg(action.name, disks.join(QStringLiteral(", ")));
}

void settle(MachineSession& session) {
    settleWith(session, [] { QCoreApplication::processEvents(); });
}

QString playReplay(MainWindow& window, MachineSession& session, const std::vector<OperatorAction>& actions,
                   const QString& path, const std::vector<ReplayPlace>& places, ReplayLayout layout) {
    constexpr double kFrame = 1.0 / 60.0;
    double now = 0.0;
    const bool fast = layout == ReplayLayout::WhenRead;
    // a fast replay delivers what was posted without polling the system (widget timers wait)
    auto deliver = [fast] { fast ? QCoreApplication::sendPostedEvents() : QCoreApplication::processEvents(); };

    // nobody watches a replay's frames: the pages render each snapshot as always, but no widget
    // paints until the replay ends (a page switch cost 3.5 ms of painting)
    const bool painting = window.updatesEnabled();
    window.setUpdatesEnabled(false);
    struct Restore {
        MainWindow& window;
        bool painting;
        ~Restore() {
            window.holdRendering(false);
            window.setUpdatesEnabled(painting);
        }
    } restore{window, painting};
    settle(session);
    std::optional<DeferredLayout> layouts;
    if (layout == ReplayLayout::WhenRead) {
        layouts.emplace();
        // the page and status line render only the snapshot an action or the end reads
        window.holdRendering(true);
    }
    for (std::size_t i = 0; i < actions.size(); ++i) {
        const OperatorAction& action = actions[i];
        // a time mark with a later action after it: the panel need not see its moment (nothing is
        // recorded with it), the next action's frames end in a snapshot
        const bool mark = action.kind == OperatorAction::Kind::Wait && i + 1 < actions.size() &&
                          actions[i + 1].t > action.t + 1e-9 && !window.recording();
        // an action for the machine alone needs no snapshot before it: its own shows the time too
        const bool unseen = mark || (goesToMachineAlone(action) && !window.recording());
        while (now + 1e-9 < action.t) {
            if (const double passed = session.advanceWhileQuiet(action.t - now, !unseen); passed > 0.0) {
                now += passed;
                if (unseen && now + 1e-9 >= action.t) {
                    break; // no snapshot came: nothing to show
                }
            } else {
                const double step = std::min(kFrame, action.t - now);
                session.advance(step);
                now += step;
            }
            deliver();
        }
        if (QString refused = refusedReplayLoad(window, action, path, i < places.size() ? places[i] : ReplayPlace{});
            !refused.isEmpty()) {
            return refused;
        }
        if (layouts && readsScreen(action)) {
            window.renderHeld();
            if (window.currentPage()->readsLayout()) {
                window.showHeldPage();
                layouts->catchUp();
            }
        }
        window.dispatcher().dispatch(action);
        if (action.kind == OperatorAction::Kind::Wait) {
            continue; // time passing asks nothing of the machine
        }
        if (i + 1 < actions.size() && actions[i + 1].t > action.t + 1e-9 && session.unchangedSinceSnapshot()) {
            // an action on the screen alone (a page, a list, a menu): the machine's snapshot stands,
            // and the time before the next action ends in a new one, as a snapshot now would
            deliver();
        } else {
            settleWith(session, deliver);
        }
    }
    settle(session);
    window.holdRendering(false);
    layouts.reset();
    settle(session);
    return {};
}

} // namespace m350::ui
