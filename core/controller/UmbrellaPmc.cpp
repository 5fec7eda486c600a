// The PMC of a FANUC machine with an umbrella carousel, as the paper's O9001 expects it: each M code
// switches an actuator and finishes (FIN) when its sensor says the motion is done. A sensor that
// never comes stops the run with `sensor_timeout` naming it, where the real machine would hang.
//   M10 clamp / M11 release the tool (drawbar, released/clamped sensors)
//   M81 magazine ready (enable), M82 turn the commanded tool's pocket to the spindle (in position)
//   M83 carousel to the spindle / M84 back (slide, at-spindle/away sensors; each starts once the
//   carousel stands in position at the other end)
//   M85 store the commanded tool as the spindle's tool (what #1000 and #1001 compare with)
#include "core/controller/MagazineDriver.h"

#include "core/params/IoPorts.h"
#include "core/devices/UmbrellaCarousel.h"
#include "core/interp/ModalInterpreter.h"
#include "core/machine/SimulatedMachine.h"
#include "core/macro/MacroError.h"

#include <cstdio>

namespace m350::controller {

namespace {

constexpr double kPmcScan = 0.01; // how often the ladder looks at a sensor, s

} // namespace

void MagazineDriver::awaitSensor(int pin, int level, int mCode) {
    double waited = 0.0;
    while (context_.machine.input(pin) != level) {
        if (waited >= context_.settings.sensorTimeout) {
            char seconds[32];
            std::snprintf(seconds, sizeof seconds, "%.1f", context_.settings.sensorTimeout);
            throw macro::MacroError::of(AlarmCode::SensorTimeout, message("pmc_sensor_timeout",
                                                                          {bilingual(describeInput(pin), describeInput(pin, true)), std::to_string(level),
                                                                           seconds, std::to_string(mCode)}));
        }
        context_.machine.blockTime(kPmcScan);
        waited += kPmcScan;
    }
}

std::optional<Message> MagazineDriver::refusedTool(int tool) const {
    if (!carousel_ || (tool >= 0 && tool <= carousel_->pocketCount())) {
        return std::nullopt;
    }
    return message("carousel_refused_tool", {std::to_string(tool), std::to_string(carousel_->pocketCount())});
}

void MagazineDriver::answerPmc(int code) {
    const config::MagazineConfig& m = context_.config.magazine;
    const int commanded = context_.interp.state().selectedTool;
    if (code >= 81 && code <= 85 && (commanded < 0 || commanded > carousel_->pocketCount())) {
        // the ladder checks the T code before it moves the magazine
        throw macro::MacroError::of(AlarmCode::InvalidArgument,
                                    message("carousel_refused_m", {std::to_string(commanded),
                                                                   std::to_string(carousel_->pocketCount()),
                                                                   std::to_string(code)}));
    }
    switch (code) {
    case 10:
    case 11:
        context_.machine.setOutput(m.drawbarOutput, code == 11 ? 1 : 0);
        awaitSensor(code == 11 ? m.releasedInput : m.clampedInput, 1, code);
        return;
    case 82: {
        devices::UmbrellaCarousel::Action turn =
            carousel_->turnTo(commanded, noseAt(context_.machine.position()), context_.machine.time());
        if (turn.crash) {
            throw macro::MacroError::of(AlarmCode::Crash, *turn.crash);
        }
        driveInPosition(context_.machine.time(), turn.seconds);
        awaitSensor(m.inPositionInput, 1, code);
        return;
    }
    case 83:
    case 84:
        if (context_.machine.output(m.slideOutput) != (code == 83 ? 1 : 0)) {
            // the ladder's interlock: the slide starts from rest, the carousel in position at the
            // other end (after an E-stop it may still be turning or sliding back)
            for (int pin : {m.inPositionInput, code == 83 ? m.awayInput : m.atSpindleInput}) {
                if (pin > 0) {
                    awaitSensor(pin, 1, code);
                }
            }
        }
        context_.machine.setOutput(m.slideOutput, code == 83 ? 1 : 0);
        awaitSensor(code == 83 ? m.atSpindleInput : m.awayInput, 1, code);
        return;
    case 85: context_.pmcSpindleTool = commanded; return;
    default: return; // M81 (ready) and the rest: nothing the carousel needs
    }
}

} // namespace m350::controller
