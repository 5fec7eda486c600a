#pragma once

#include "core/controller/PanelStatus.h"
#include "core/machine/MachineTypes.h"

#include <QCoreApplication>
#include <QString>

namespace m350::ui {

// The words of the status line and the DRO, from the firmware's string table (the disambiguation
// names its msg id, which scripts/fill-translations.py uses to take the Chinese from the table).
class PanelText {
    Q_DECLARE_TR_FUNCTIONS(m350::ui::PanelText)
public:
    // The mode field, msg 0-11.
    enum class Mode { Cont, Step, Mpg, Zero, GoWorkZero, Home, Probe, Middle, Auto, Simulate, Wheel, Mdi };
    // The state field, msg 20-26.
    enum class State { Ready, Busy, Reset, Error, Alarm, Forward, Reverse };

    static QString mode(Mode mode);
    static QString modeKey(Mode mode);   // untranslated, for --state: "CONT", "WHEEL" ...
    static QString state(State state);
    static QString stateKey(State state); // "READY", "BUSY" ...
    static QString spindle(machine::SpindleState state);
    static QString axis(int axis); // X Y Z 4th 5th: the axis's place, as the firmware's softkeys say it
    // The axis's name on this machine: X Y Z, then the 4th and 5th as the parameters call them (A B
    // C); a 4th or 5th the machine lacks keeps its place's name.
    static QString axis(int axis, const controller::PanelStatus& status);
    static QString axisUnit(int axis, const controller::PanelStatus& status); // mm, or deg when it turns
    // A firmware text about the 4th or 5th axis ("Clear 4th", "机械4th轴回") with the machine's name
    // for it ("Clear A", "机械A轴回").
    static QString withAxisName(const QString& text, int axis, const controller::PanelStatus& status);
    // True while the panel speaks Chinese: names that come from the core in both languages
    // (IO functions) pick their zh or en form by it.
    static bool chinese();
};

} // namespace m350::ui
