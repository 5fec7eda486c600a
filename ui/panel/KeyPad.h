#pragma once

#include "ui/actions/OperatorAction.h"
#include "ui/actions/PanelKey.h"
#include "ui/session/PanelSnapshot.h"

#include <QMap>
#include <QWidget>

#include <functional>

class QPushButton;

namespace m350::ui {

class HandwheelWidget;

// The panel's keys beside the screen, as buttons: page keys, cycle keys, mode keys, jog keys,
// jog steps, overrides and spindle keys, and the handwheel. The buttons are the keys of
// PanelKey::all() that have a place on the pad; every button produces the same OperatorAction its
// keyboard shortcut does; lamps follow the snapshot.
class KeyPad : public QWidget {
    Q_OBJECT
public:
    using Sink = std::function<void(const OperatorAction&)>;
    explicit KeyPad(Sink sink, QWidget* parent = nullptr);
    void render(const PanelSnapshot& snapshot);
    QPushButton* button(const QString& key) const { return buttons_.value(key); }
    HandwheelWidget* handwheel() const { return wheel_; }

protected:
    void changeEvent(QEvent* event) override;

private:
    QPushButton* addKey(const PanelKey& key);
    void retranslate();
    Sink sink_;
    QMap<QString, QPushButton*> buttons_;
    // each snapshot goes over these, not over the names (a replay renders one every action)
    struct Shown {
        const PanelKey* key;
        QPushButton* button;
        bool lamp; // its "lamp" property as last set
    };
    std::vector<Shown> shown_;
    HandwheelWidget* wheel_;
};

} // namespace m350::ui
