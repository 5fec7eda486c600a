#include "ui/panel/PanelMode.h"

#include "ui/pages/PageId.h"

namespace m350::ui {

using Run = controller::PanelStatus::Run;

PanelText::Mode displayedMode(const PanelSnapshot& snapshot, const QString& page) {
    const controller::PanelStatus& s = snapshot.status;
    if (s.guide) {
        return PanelText::Mode::Wheel;
    }
    if (snapshot.simulation.active() && snapshot.activity == Activity::None) {
        return PanelText::Mode::Simulate; // 仿真 while the machine itself does nothing
    }
    switch (snapshot.activity) {
    case Activity::Auto:
    case Activity::Hook: return PanelText::Mode::Auto;
    case Activity::Mdi:
    case Activity::SpindleKey: return PanelText::Mode::Mdi;
    case Activity::Homing: return PanelText::Mode::Home;
    case Activity::Probe: return PanelText::Mode::Probe;
    case Activity::None: break;
    }
    if (page == PageId::mdi) {
        return PanelText::Mode::Mdi;
    }
    if (page == PageId::probe) {
        return PanelText::Mode::Probe;
    }
    switch (s.jogMode) {
    case controller::JogMode::Continuous: return PanelText::Mode::Cont;
    case controller::JogMode::Step: return PanelText::Mode::Step;
    case controller::JogMode::Mpg: return PanelText::Mode::Mpg;
    }
    return PanelText::Mode::Cont;
}

PanelText::State displayedState(const PanelSnapshot& snapshot) {
    const controller::PanelStatus& s = snapshot.status;
    switch (s.run) {
    case Run::Alarm: return PanelText::State::Error;
    case Run::EStop: return PanelText::State::Alarm;
    case Run::Hold: // 暂停 shows on the message line; the machine is still in a run
    case Run::Running:
        if (s.guide && s.guideDirection > 0) {
            return PanelText::State::Forward;
        }
        if (s.guide && s.guideDirection < 0) {
            return PanelText::State::Reverse;
        }
        return PanelText::State::Busy;
    case Run::Idle:
    case Run::Finished: break;
    }
    if (snapshot.simulation.run == SimulationView::Run::Running) {
        return PanelText::State::Busy;
    }
    return s.jogging ? PanelText::State::Busy : PanelText::State::Ready;
}

} // namespace m350::ui
