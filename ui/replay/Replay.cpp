#include "ui/replay/Replay.h"

#include "ui/panel/MainWindow.h"
#include "ui/session/MachineSession.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonDocument>
#include <QJsonParseError>

namespace m350::ui {

std::optional<std::vector<OperatorAction>> readReplay(const QString& path, QString* error) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        *error = QStringLiteral("%1: cannot read: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    std::vector<OperatorAction> actions;
    int lineNumber = 0;
    double previous = 0.0;
    while (!file.atEnd()) {
        ++lineNumber;
        QByteArray line = file.readLine().trimmed();
        if (line.isEmpty() || line.startsWith("//")) {
            continue;
        }
        QJsonParseError parse{};
        QJsonDocument doc = QJsonDocument::fromJson(line, &parse);
        if (parse.error != QJsonParseError::NoError || !doc.isObject()) {
            *error = QStringLiteral("%1:%2:%3: not a JSON object: %4")
                         .arg(path)
                         .arg(lineNumber)
                         .arg(parse.offset + 1)
                         .arg(parse.error != QJsonParseError::NoError ? parse.errorString() : QStringLiteral("expected {...}"));
            return std::nullopt;
        }
        QString why;
        auto action = OperatorAction::fromJson(doc.object(), &why);
        if (!action) {
            *error = QStringLiteral("%1:%2:1: %3").arg(path).arg(lineNumber).arg(why);
            return std::nullopt;
        }
        if (action->t < previous) {
            *error = QStringLiteral("%1:%2:1: t = %3 comes before the previous action's %4 (actions must be in time order)")
                         .arg(path)
                         .arg(lineNumber)
                         .arg(action->t)
                         .arg(previous);
            return std::nullopt;
        }
        previous = action->t;
        actions.push_back(*action);
    }
    return actions;
}

void settle(MachineSession& session) {
    session.sync();
    QCoreApplication::processEvents();
    QCoreApplication::processEvents();
}

void playReplay(MainWindow& window, MachineSession& session, const std::vector<OperatorAction>& actions) {
    constexpr double kFrame = 1.0 / 60.0;
    double now = 0.0;
    settle(session);
    for (const OperatorAction& action : actions) {
        while (now + 1e-9 < action.t) {
            double step = std::min(kFrame, action.t - now);
            session.advance(step);
            now += step;
            QCoreApplication::processEvents();
        }
        window.dispatcher().dispatch(action);
        settle(session);
    }
}

} // namespace m350::ui
