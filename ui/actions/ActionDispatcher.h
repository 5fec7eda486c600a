#pragma once

#include "ui/actions/OperatorAction.h"

#include <QObject>

namespace m350::ui {

class MachineSession;
class PanelScreen;
struct PanelKey;

// The one path every operator action takes, whoever produced it (keyboard, a click, a test, a
// replay): machine keys become session commands, page keys change the page, softkeys, arrows,
// Enter and Esc go to the open prompt or the current page.
class ActionDispatcher : public QObject {
    Q_OBJECT
public:
    ActionDispatcher(PanelScreen& screen, MachineSession& session, QObject* parent = nullptr);
    void dispatch(const OperatorAction& action);

signals:
    // After each action, for the recorder (t is filled in by whoever records).
    void dispatched(const m350::ui::OperatorAction& action);

private:
    bool machineKey(const PanelKey* key);
    void jogKey(const PanelKey& key, OperatorAction::Kind kind);
    bool axisPresent(int axis) const;
    void screenKey(const PanelKey* key, const QString& name); // key: nullptr for a name the table lacks
    void force(const OperatorAction::Force& force);
    PanelScreen& screen_;
    MachineSession& session_;
};

} // namespace m350::ui
