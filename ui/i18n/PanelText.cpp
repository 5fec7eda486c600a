#include "ui/i18n/PanelText.h"

namespace m350::ui {

QString PanelText::mode(Mode mode) {
    switch (mode) {
    case Mode::Cont: return tr("CONT", "msg 0");
    case Mode::Step: return tr("STEP", "msg 1");
    case Mode::Mpg: return tr("MPG", "msg 2");
    case Mode::Zero: return tr("ZERO", "msg 3");
    case Mode::GoWorkZero: return tr("GOTOZ", "msg 4");
    case Mode::Home: return tr("HOME", "msg 5");
    case Mode::Probe: return tr("PROBE", "msg 6");
    case Mode::Middle: return tr("MIDDLE", "msg 7");
    case Mode::Auto: return tr("AUTO", "msg 8");
    case Mode::Simulate: return tr("SL", "msg 9");
    case Mode::Wheel: return tr("WHEEL", "msg 10");
    case Mode::Mdi: return tr("MDI", "msg 11");
    }
    return {};
}

QString PanelText::modeKey(Mode mode) {
    static const char* const keys[] = {"CONT", "STEP", "MPG", "ZERO", "GOTOZ", "HOME",
                                       "PROBE", "MIDDLE", "AUTO", "SL", "WHEEL", "MDI"};
    return QString::fromLatin1(keys[static_cast<int>(mode)]);
}

QString PanelText::state(State state) {
    switch (state) {
    case State::Ready: return tr("READY", "msg 20");
    case State::Busy: return tr("BUSY", "msg 21");
    case State::Reset: return tr("RESET", "msg 22");
    case State::Error: return tr("ERROR", "msg 23");
    case State::Alarm: return tr("ALARM", "msg 24");
    case State::Forward: return tr("WHEEL", "msg 25");
    case State::Reverse: return tr("WHEEL REV", "msg 26");
    }
    return {};
}

QString PanelText::stateKey(State state) {
    static const char* const keys[] = {"READY", "BUSY", "RESET", "ERROR", "ALARM", "WHEEL", "WHEEL_REV"};
    return QString::fromLatin1(keys[static_cast<int>(state)]);
}

QString PanelText::spindle(machine::SpindleState state) {
    switch (state) {
    case machine::SpindleState::Stop: return tr("STOP", "msg 40");
    case machine::SpindleState::Forward: return tr("FWD", "msg 41");
    case machine::SpindleState::Reverse: return tr("REV", "msg 42");
    case machine::SpindleState::Jog: return tr("JOG", "msg 43");
    case machine::SpindleState::Tap: return tr("TAP", "msg 44");
    case machine::SpindleState::Orient: return tr("PRCE STOP", "msg 45");
    }
    return {};
}

bool PanelText::chinese() { return mode(Mode::Cont) != QLatin1String("CONT"); }

QString PanelText::axis(int axis) {
    static const char* const names[] = {"X", "Y", "Z", "4th", "5th"};
    return QString::fromLatin1(names[axis]);
}

QString PanelText::axis(int axis, const controller::PanelStatus& status) {
    const auto i = static_cast<std::size_t>(axis);
    return status.axisShown[i] ? QString(QChar::fromLatin1(status.axisName[i])) : PanelText::axis(axis);
}

QString PanelText::axisUnit(int axis, const controller::PanelStatus& status) {
    return status.axisRotary[static_cast<std::size_t>(axis)] ? tr("deg") : tr("mm");
}

QString PanelText::withAxisName(const QString& text, int axis, const controller::PanelStatus& status) {
    if (axis < 3 || !status.axisShown[static_cast<std::size_t>(axis)]) {
        return text;
    }
    QString named = text;
    return named.replace(PanelText::axis(axis), PanelText::axis(axis, status));
}

} // namespace m350::ui
