#include "ui/actions/KeyboardMap.h"

#include <QHash>
#include <QKeyEvent>

namespace m350::ui {

namespace {

const QHash<int, QString>& ctrlJogKeys() {
    static const QHash<int, QString> keys{{Qt::Key_Right, "JOG_X+"}, {Qt::Key_Left, "JOG_X-"},
                                          {Qt::Key_Up, "JOG_Y+"},    {Qt::Key_Down, "JOG_Y-"},
                                          {Qt::Key_PageUp, "JOG_Z+"}, {Qt::Key_PageDown, "JOG_Z-"}};
    return keys;
}

const QHash<int, QString>& ctrlKeys() {
    static const QHash<int, QString> keys{
        {Qt::Key_M, "MONITOR"}, {Qt::Key_D, "MDI"},    {Qt::Key_I, "IO"},        {Qt::Key_P, "PROBE"},
        {Qt::Key_3, "M3"},      {Qt::Key_4, "M4"},     {Qt::Key_5, "M5"},        {Qt::Key_S, "SPINDLE"},
        {Qt::Key_J, "CONT_STEP_MPG"}, {Qt::Key_W, "MPG_RUN"}, {Qt::Key_0, "FRO_100"},
        {Qt::Key_Equal, "FRO_UP"}, {Qt::Key_Plus, "FRO_UP"}, {Qt::Key_Minus, "FRO_DOWN"}, {Qt::Key_H, "HIGH_LOW"}};
    return keys;
}

const QHash<int, QString>& plainKeys() {
    static const QHash<int, QString> keys{
        {Qt::Key_Return, "ENTER"}, {Qt::Key_Enter, "ENTER"}, {Qt::Key_Escape, "ESC"},  {Qt::Key_Up, "UP"},
        {Qt::Key_Down, "DOWN"},    {Qt::Key_Left, "LEFT"},   {Qt::Key_Right, "RIGHT"}, {Qt::Key_Backspace, "BACKSPACE"},
        {Qt::Key_F9, "START"},     {Qt::Key_F10, "PAUSE"},   {Qt::Key_F11, "RESET"},   {Qt::Key_F12, "ESTOP"}};
    return keys;
}

} // namespace

std::optional<OperatorAction> actionForKey(const QKeyEvent& event, bool pressed) {
    const int key = event.key();
    const Qt::KeyboardModifiers mods = event.modifiers() & ~Qt::KeypadModifier;
    if (mods == Qt::ControlModifier && ctrlJogKeys().contains(key)) {
        if (event.isAutoRepeat()) {
            return std::nullopt; // held: one press, one release
        }
        QString name = ctrlJogKeys().value(key);
        return pressed ? OperatorAction::keyDown(name) : OperatorAction::keyUp(name);
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
    if (mods == Qt::ControlModifier && ctrlKeys().contains(key)) {
        return OperatorAction::key(ctrlKeys().value(key));
    }
    if (mods == Qt::NoModifier && plainKeys().contains(key)) {
        return OperatorAction::key(plainKeys().value(key));
    }
    const QString text = event.text();
    if ((mods == Qt::NoModifier || mods == Qt::ShiftModifier) && !text.isEmpty() && text.at(0).isPrint()) {
        return OperatorAction::typed(text);
    }
    return std::nullopt;
}

} // namespace m350::ui
