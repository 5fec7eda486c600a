#pragma once

#include <QKeyCombination>
#include <QLatin1StringView>
#include <QList>
#include <QString>

namespace m350::ui {

class MachineSession;
class PanelPrompt;

// One key of the panel: a button beside the screen, or a key the PC keyboard stands in for. The
// table of them, PanelKey::all(), is the one place a key is written down: replays and recordings
// spell it by `name`, the KeyPad shows its label at `place` and lights its `lamp`, the keyboard
// map reads `keyboard`, and the dispatcher does what `role` says.
struct PanelKey {
    enum class Role {
        Machine,      // `command` on the session, whatever page is shown
        Jog,          // moves `axis` towards `direction` while held; a press alone is a tap
        JogStepInput, // asks the step distance (STEP_INPUT)
        Page,         // opens `page`
        Softkey,      // softkey `softkey` of the current page (F1-F6)
        Screen,       // for the open prompt (`onPrompt`), else the current page (ENTER, ESC, arrows)
        Wheel,        // the handwheel's axis switch (`axis`) or its x1/x10/x100 switch (`argument`)
    };
    enum class Lamp { None, Always, Running, Hold, Spindle, Guide, JogHighSpeed, JogStep };
    using Command = void (*)(MachineSession& session, double argument);
    using PromptCommand = void (*)(PanelPrompt& prompt);
    struct Label {
        const char* source = nullptr;  // in KeyPad's translation context; nullptr: see `caption`
        const char* comment = nullptr; // the firmware's msg id where the word is the firmware's
    };
    struct Place {
        int row = -1; // on the KeyPad, top to bottom; -1: not a button there
        int column = 0;
        int width = 1;
    };

    QString name;
    Role role = Role::Screen;
    Label label{};
    QLatin1StringView caption{}; // the KeyPad's text where it is no word (0.001, X+); empty: the name
    Command command = nullptr;
    double argument = 0.0; // the command's: M code, K number, override step (%), jog step (mm)
    QLatin1StringView page{};
    int axis = -1;     // Jog, Wheel: 0..4 = X Y Z A B
    int direction = 0; // Jog: +1 or -1
    int softkey = 0;   // Softkey: 1-6
    PromptCommand onPrompt = nullptr;
    Lamp lamp = Lamp::None;
    Place place{};
    QList<QKeyCombination> keyboard{}; // its PC keyboard keys

    static const QList<PanelKey>& all();
    static const PanelKey* named(const QString& name); // nullptr: no key of the panel
};

} // namespace m350::ui
