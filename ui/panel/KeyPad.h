#pragma once

#include "ui/actions/OperatorAction.h"
#include "ui/session/PanelSnapshot.h"

#include <QMap>
#include <QWidget>

#include <functional>

class QPushButton;

namespace m350::ui {

class HandwheelWidget;

// The panel's keys beside the screen, as buttons: page keys, cycle keys, mode keys, jog keys,
// jog steps, overrides and spindle keys, and the handwheel. Every button produces the same
// OperatorAction its keyboard shortcut does; lamps follow the snapshot.
class KeyPad : public QWidget {
    Q_OBJECT
public:
    using Sink = std::function<void(const OperatorAction&)>;
    explicit KeyPad(Sink sink, QWidget* parent = nullptr);
    void render(const PanelSnapshot& snapshot);
    QPushButton* button(const QString& key) const { return buttons_.value(key); }
    HandwheelWidget* handwheel() const { return wheel_; }
    // The page keys of pages the window has are enabled; the others say they come later.
    void setAvailablePages(const QStringList& ids);
    static const QMap<QString, QString>& pageKeys(); // key name -> page id
    static const QStringList& mCodeKeys();           // M3 M4 M5 M8 M9 M10 M11 M19: their hook or the M code
    static const QStringList& userKeys();            // K1-K7: what params 210-216 make of them

protected:
    void changeEvent(QEvent* event) override;

private:
    QPushButton* addKey(const QString& key, QWidget* parent);
    void retranslate();
    Sink sink_;
    QMap<QString, QPushButton*> buttons_;
    HandwheelWidget* wheel_;
    QStringList availablePages_;
};

} // namespace m350::ui
