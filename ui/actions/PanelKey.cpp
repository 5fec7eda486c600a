#include "ui/actions/PanelKey.h"

#include "ui/pages/PageId.h"
#include "ui/pages/PanelPrompt.h"
#include "ui/session/MachineSession.h"

#include <QCoreApplication>
#include <QHash>

namespace m350::ui {

namespace {

using Role = PanelKey::Role;
using Lamp = PanelKey::Lamp;

void start(MachineSession& session, double) { session.start(); }
void pause(MachineSession& session, double) { session.pause(); }
void reset(MachineSession& session, double) { session.reset(); }
void emergencyStop(MachineSession& session, double) { session.emergencyStop(); }
void externStart(MachineSession& session, double) { session.pressExternStart(); }
void cycleJogMode(MachineSession& session, double) { session.cycleJogMode(); }
void toggleGuide(MachineSession& session, double) { session.toggleHandwheelGuide(); }
void toggleJogSpeed(MachineSession& session, double) { session.toggleJogHighSpeed(); }
void jogStep(MachineSession& session, double millimetres) { session.setJogStep(millimetres); }
// 0 is SPINDLE (toggle); 3 4 5 8 9 10 11 19 the M-code keys (their hooks or the M code)
void spindleKey(MachineSession& session, double code) { session.spindleKey(static_cast<int>(code)); }
// K1-K7: what params 210-216 make of them
void userKey(MachineSession& session, double number) { session.userKey(static_cast<int>(number)); }
// 0: 100 %, +10 / -10
void feedOverride(MachineSession& session, double step) { session.feedOverrideKey(static_cast<int>(step)); }
void spindleOverride(MachineSession& session, double step) { session.spindleOverrideKey(static_cast<int>(step)); }

void confirm(PanelPrompt& prompt) { prompt.confirm(); }
void cancel(PanelPrompt& prompt) { prompt.cancel(); }
void backspace(PanelPrompt& prompt) { prompt.backspace(); }

PanelKey mCodeKey(int code, PanelKey::Place place, QList<QKeyCombination> keyboard = {}) {
    return {.name = QStringLiteral("M%1").arg(code),
            .role = Role::Machine,
            .command = spindleKey,
            .argument = static_cast<double>(code),
            .place = place,
            .keyboard = std::move(keyboard)};
}

// K1-K7 are Ctrl+F1-F7 on the keyboard.
PanelKey userKeyOf(int number, PanelKey::Place place) {
    return {.name = QStringLiteral("K%1").arg(number),
            .role = Role::Machine,
            .command = userKey,
            .argument = static_cast<double>(number),
            .place = place,
            .keyboard = {Qt::CTRL | Qt::Key(Qt::Key_F1 + number - 1)}};
}

// Axes 0-2 are X Y Z, 3 and 4 the 4th and 5th (A, B): JOG_A+ is labelled 4th+.
PanelKey jogKey(int axis, int direction, QList<QKeyCombination> keyboard = {}) {
    static const char* const captions[5][2] = {{"X+", "X-"}, {"Y+", "Y-"}, {"Z+", "Z-"}, {"4th+", "4th-"}, {"5th+", "5th-"}};
    const char* caption = captions[axis][direction > 0 ? 0 : 1];
    return {.name = QStringLiteral("JOG_") + QChar("XYZAB"[axis]) + QChar(direction > 0 ? '+' : '-'),
            .role = Role::Jog,
            .caption = QLatin1StringView(caption),
            .axis = axis,
            .direction = direction,
            .place = {direction > 0 ? 3 : 4, axis},
            .keyboard = std::move(keyboard)};
}

// 0.001 .. 1 are Alt+1 .. Alt+4 on the keyboard.
PanelKey stepKey(const char* millimetres, int column) {
    return {.name = QStringLiteral("STEP_") + QLatin1StringView(millimetres),
            .role = Role::Machine,
            .caption = QLatin1StringView(millimetres),
            .command = jogStep,
            .argument = QByteArray(millimetres).toDouble(),
            .lamp = Lamp::JogStep,
            .place = {2, column},
            .keyboard = {Qt::ALT | Qt::Key(Qt::Key_1 + column)}};
}

// The handwheel's switches, for a window without the key panel (800x480): Alt+X Y Z A B choose the
// axis (A and B: the 4th and 5th whatever they are named), Alt+6 7 8 the x1 x10 x100 step.
PanelKey wheelAxisKey(int axis, Qt::Key key) {
    return {.name = QStringLiteral("WHEEL_") + QChar("XYZ45"[axis]), .role = Role::Wheel, .axis = axis,
            .keyboard = {Qt::ALT | key}};
}

PanelKey wheelStepKey(int step, Qt::Key key) {
    return {.name = QStringLiteral("WHEEL_X%1").arg(step), .role = Role::Wheel, .argument = double(step),
            .keyboard = {Qt::ALT | key}};
}

PanelKey softkeyKey(int number) {
    return {.name = QStringLiteral("F%1").arg(number),
            .role = Role::Softkey,
            .softkey = number,
            .keyboard = {Qt::Key(Qt::Key_F1 + number - 1)}};
}

QList<PanelKey> makeKeys() {
    QList<PanelKey> keys{
        {.name = "MONITOR", .role = Role::Page, .label = QT_TRANSLATE_NOOP3("m350::ui::KeyPad", "Monitor", "msg 300"),
         .page = PageId::monitor, .place = {0, 0}, .keyboard = {Qt::CTRL | Qt::Key_M}},
        {.name = "PROGRAM", .role = Role::Page, .label = QT_TRANSLATE_NOOP3("m350::ui::KeyPad", "Program", "msg 301"),
         .page = PageId::program, .place = {0, 1}, .keyboard = {Qt::CTRL | Qt::Key_O}},
        {.name = "PARAM", .role = Role::Page, .label = QT_TRANSLATE_NOOP3("m350::ui::KeyPad", "Param", "msg 302"),
         .page = PageId::param, .place = {0, 2}, .keyboard = {Qt::CTRL | Qt::Key_R}},
        {.name = "IO", .role = Role::Page, .label = QT_TRANSLATE_NOOP3("m350::ui::KeyPad", "IO", "msg 303"),
         .page = PageId::io, .place = {0, 3}, .keyboard = {Qt::CTRL | Qt::Key_I}},
        {.name = "LOG", .role = Role::Page, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "Log")},
         .page = PageId::log, .place = {0, 4}, .keyboard = {Qt::CTRL | Qt::Key_L}},
        {.name = "SYSTEM", .role = Role::Page, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "System")},
         .page = PageId::system, .place = {0, 5}, .keyboard = {Qt::CTRL | Qt::Key_Y}},
        {.name = "MDI", .role = Role::Page, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "MDI")},
         .page = PageId::mdi, .place = {1, 0}, .keyboard = {Qt::CTRL | Qt::Key_D}},
        {.name = "PROBE", .role = Role::Page, .label = QT_TRANSLATE_NOOP3("m350::ui::KeyPad", "Probe", "msg 313"),
         .page = PageId::probe, .place = {1, 1}, .keyboard = {Qt::CTRL | Qt::Key_P}},
        {.name = "CONT_STEP_MPG", .role = Role::Machine,
         .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "CONT\nSTEP MPG")}, .command = cycleJogMode,
         .lamp = Lamp::Always, .place = {1, 2}, .keyboard = {Qt::CTRL | Qt::Key_J}},
        {.name = "MPG_RUN", .role = Role::Machine, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "MPG RUN")},
         .command = toggleGuide, .lamp = Lamp::Guide, .place = {1, 3}, .keyboard = {Qt::CTRL | Qt::Key_W}},
        {.name = "HIGH_LOW", .role = Role::Machine, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "Hi/Lo")},
         .command = toggleJogSpeed, .lamp = Lamp::JogHighSpeed, .place = {1, 4}, .keyboard = {Qt::CTRL | Qt::Key_H}},
        {.name = "STEP_INPUT", .role = Role::JogStepInput, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "Step...")},
         .place = {1, 5}, .keyboard = {Qt::ALT | Qt::Key_5}},
        stepKey("0.001", 0),
        stepKey("0.01", 1),
        stepKey("0.1", 2),
        stepKey("1", 3),
        {.name = "EXT_START", .role = Role::Machine, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "Ext START")},
         .command = externStart, .place = {2, 4}, .keyboard = {Qt::SHIFT | Qt::Key_F9}},
        {.name = "ESTOP", .role = Role::Machine, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "E-STOP")},
         .command = emergencyStop, .place = {2, 5}, .keyboard = {Qt::Key_F12}},
        {.name = "START", .role = Role::Machine, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "START")},
         .command = start, .lamp = Lamp::Running, .place = {3, 5}, .keyboard = {Qt::Key_F9}},
        {.name = "PAUSE", .role = Role::Machine, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "PAUSE")},
         .command = pause, .lamp = Lamp::Hold, .place = {4, 5}, .keyboard = {Qt::Key_F10}},
        {.name = "FRO_100", .role = Role::Machine, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "FRO\n100%")},
         .command = feedOverride, .argument = 0, .place = {5, 0}, .keyboard = {Qt::CTRL | Qt::Key_0}},
        {.name = "FRO_UP", .role = Role::Machine, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "FRO\n+10%")},
         .command = feedOverride, .argument = 10, .place = {5, 1},
         .keyboard = {Qt::CTRL | Qt::Key_Equal, Qt::CTRL | Qt::Key_Plus}},
        {.name = "FRO_DOWN", .role = Role::Machine, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "FRO\n-10%")},
         .command = feedOverride, .argument = -10, .place = {5, 2}, .keyboard = {Qt::CTRL | Qt::Key_Minus}},
        {.name = "SRO_100", .role = Role::Machine, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "SRO\n100%")},
         .command = spindleOverride, .argument = 0, .place = {5, 3}, .keyboard = {Qt::ALT | Qt::Key_0}},
        {.name = "SRO_UP", .role = Role::Machine, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "SRO\n+10%")},
         .command = spindleOverride, .argument = 10, .place = {5, 4},
         .keyboard = {Qt::ALT | Qt::Key_Equal, Qt::ALT | Qt::Key_Plus}},
        {.name = "SRO_DOWN", .role = Role::Machine, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "SRO\n-10%")},
         .command = spindleOverride, .argument = -10, .place = {5, 5}, .keyboard = {Qt::ALT | Qt::Key_Minus}},
        {.name = "SPINDLE", .role = Role::Machine, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "Spindle")},
         .command = spindleKey, .argument = 0, .lamp = Lamp::Spindle, .place = {6, 0},
         .keyboard = {Qt::CTRL | Qt::Key_S}},
        mCodeKey(3, {6, 1}, {Qt::CTRL | Qt::Key_3}),
        mCodeKey(4, {6, 2}, {Qt::CTRL | Qt::Key_4}),
        mCodeKey(5, {6, 3}, {Qt::CTRL | Qt::Key_5}),
        {.name = "RESET", .role = Role::Machine, .label = {QT_TRANSLATE_NOOP("m350::ui::KeyPad", "RESET")},
         .command = reset, .place = {6, 4, 2}, .keyboard = {Qt::Key_F11}},
        userKeyOf(7, {8, 0}),
        mCodeKey(8, {8, 1}, {Qt::CTRL | Qt::Key_8}),
        mCodeKey(9, {8, 2}, {Qt::CTRL | Qt::Key_9}),
        mCodeKey(10, {8, 3}, {Qt::CTRL | Qt::ALT | Qt::Key_0}),
        mCodeKey(11, {8, 4}, {Qt::CTRL | Qt::ALT | Qt::Key_1}),
        mCodeKey(19, {8, 5}, {Qt::CTRL | Qt::ALT | Qt::Key_9}),
        {.name = "ENTER", .onPrompt = confirm, .keyboard = {Qt::Key_Return, Qt::Key_Enter}},
        {.name = "ESC", .onPrompt = cancel, .keyboard = {Qt::Key_Escape}},
        {.name = "BACKSPACE", .onPrompt = backspace, .keyboard = {Qt::Key_Backspace}},
        {.name = "UP", .keyboard = {Qt::Key_Up}},
        {.name = "DOWN", .keyboard = {Qt::Key_Down}},
        {.name = "LEFT", .keyboard = {Qt::Key_Left}},
        {.name = "RIGHT", .keyboard = {Qt::Key_Right}},
    };
    keys << wheelAxisKey(0, Qt::Key_X) << wheelAxisKey(1, Qt::Key_Y) << wheelAxisKey(2, Qt::Key_Z)
         << wheelAxisKey(3, Qt::Key_A) << wheelAxisKey(4, Qt::Key_B) << wheelStepKey(1, Qt::Key_6)
         << wheelStepKey(10, Qt::Key_7) << wheelStepKey(100, Qt::Key_8);
    for (int number = 1; number <= 6; ++number) {
        keys << userKeyOf(number, {7, number - 1}) << softkeyKey(number);
    }
    // Ctrl+arrows and Ctrl+PgUp/PgDn jog X Y Z while held
    keys << jogKey(0, 1, {Qt::CTRL | Qt::Key_Right}) << jogKey(0, -1, {Qt::CTRL | Qt::Key_Left})
         << jogKey(1, 1, {Qt::CTRL | Qt::Key_Up}) << jogKey(1, -1, {Qt::CTRL | Qt::Key_Down})
         << jogKey(2, 1, {Qt::CTRL | Qt::Key_PageUp}) << jogKey(2, -1, {Qt::CTRL | Qt::Key_PageDown});
    // Ctrl+Home/End the 4th, Ctrl+Insert/Delete the 5th
    keys << jogKey(3, 1, {Qt::CTRL | Qt::Key_Home}) << jogKey(3, -1, {Qt::CTRL | Qt::Key_End})
         << jogKey(4, 1, {Qt::CTRL | Qt::Key_Insert}) << jogKey(4, -1, {Qt::CTRL | Qt::Key_Delete});
    return keys;
}

} // namespace

const QList<PanelKey>& PanelKey::all() {
    static const QList<PanelKey> keys = makeKeys();
    return keys;
}

const PanelKey* PanelKey::named(const QString& name) {
    static const QHash<QString, const PanelKey*> byName = [] {
        QHash<QString, const PanelKey*> table;
        for (const PanelKey& key : all()) {
            table.insert(key.name, &key);
        }
        return table;
    }();
    return byName.value(name, nullptr);
}

} // namespace m350::ui
