#include "ui/actions/KeyboardMap.h"

#include "ui/actions/PanelKey.h"

#include <QHash>
#include <QKeyEvent>

namespace m350::ui {

namespace {

// PanelKey::all()'s keyboard keys: key and modifiers -> the panel's key.
const QHash<int, const PanelKey*>& keysByCombination() {
    static const QHash<int, const PanelKey*> keys = [] {
        QHash<int, const PanelKey*> table;
        for (const PanelKey& key : PanelKey::all()) {
            for (QKeyCombination combination : key.keyboard) {
                table.insert(combination.toCombined(), &key);
            }
        }
        return table;
    }();
    return keys;
}

} // namespace

std::optional<OperatorAction> actionForKey(const QKeyEvent& event, bool pressed) {
    const int key = event.key();
    const Qt::KeyboardModifiers mods = event.modifiers() & ~Qt::KeypadModifier;
    const PanelKey* panelKey = keysByCombination().value(QKeyCombination(mods, Qt::Key(key)).toCombined());
    if (panelKey && panelKey->role == PanelKey::Role::Jog) {
        if (event.isAutoRepeat()) {
            return std::nullopt; // held: one press, one release
        }
        return pressed ? OperatorAction::keyDown(panelKey->name) : OperatorAction::keyUp(panelKey->name);
    }
    if (!pressed) {
        return std::nullopt;
    }
    if (key >= Qt::Key_F1 && key <= Qt::Key_F6 && (mods == Qt::NoModifier || mods == Qt::ShiftModifier)) {
        return OperatorAction::softkeyPress(key - Qt::Key_F1 + 1 + (mods == Qt::ShiftModifier ? 6 : 0));
    }
    if (mods == Qt::AltModifier && (key == Qt::Key_Left || key == Qt::Key_Right)) {
        return OperatorAction::wheelTurn(-1, 1, key == Qt::Key_Right ? 1 : -1, 0.05);
    }
    if (panelKey) {
        return OperatorAction::key(panelKey->name);
    }
    const QString text = event.text();
    if ((mods == Qt::NoModifier || mods == Qt::ShiftModifier) && !text.isEmpty() && text.at(0).isPrint()) {
        return OperatorAction::typed(text);
    }
    return std::nullopt;
}

} // namespace m350::ui
