#pragma once

#include "core/common/Numeric.h"
#include "core/config/MachineConfig.h"
#include "core/controller/RunSettings.h"
#include "core/controller/TraceWriter.h"
#include "core/devices/Magazine.h"
#include "core/machine/MachineTypes.h"
#include "core/params/ParameterNumbers.h"

#include <Eigen/Core>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace m350::devices {
class LinearRack;
class ServoDisc;
class UmbrellaCarousel;
class MultiHead;
} // namespace m350::devices

namespace m350::machine {
class SimulatedMachine;
}

namespace m350::interp {
class ModalInterpreter;
}

namespace m350::controller {

// The magazine device of a machine folder and its wiring to the machine: builds the device, feeds
// it every move, drawbar and actuator switch, drives its sensors in virtual time (clamp cylinder,
// slide, disc or carousel in position), plays a FANUC carousel's PMC, and throws what the hardware
// would suffer as a `crash` MacroError, so the alarm names the macro line that caused it.
class MagazineDriver {
public:
    // What the driver works on; all of it belongs to the Controller and outlives the driver.
    struct Context {
        const config::MachineConfig& config;
        const RunSettings& settings;
        machine::SimulatedMachine& machine;
        const interp::ModalInterpreter& interp;
        int& pmcSpindleTool;                      // a FANUC's spindle tool as M85 stores it
        std::map<int, TraceSource>& inputSource;  // input -> the line that made it change
        std::function<TraceSource()> source;      // the line executing now
    };

    explicit MagazineDriver(Context context);
    ~MagazineDriver();
    MagazineDriver(const MagazineDriver&) = delete;
    MagazineDriver& operator=(const MagazineDriver&) = delete;

    // (Re)builds the device the machine folder describes from the parameters as they stand, with
    // the tool param 800 (M350) or the PMC names in the spindle and every other tool in its pocket.
    void build();
    // The device, nullptr when the machine has none.
    const devices::Magazine* device() const { return device_.get(); }
    // The device as its kind, nullptr when it is another (what the machine view draws).
    const devices::LinearRack* rack() const { return rack_; }
    const devices::ServoDisc* disc() const { return disc_; }
    const devices::UmbrellaCarousel* carousel() const { return carousel_; }
    const devices::MultiHead* multiHead() const { return multiHead_; }
    // A rack on the gantry: how far the spindle nose stands from its forks in Y (0 with the slide
    // out, [magazine] slide_travel with it in); the forks stand at the spindle's Y less this.
    double gantryNoseY() const { return slideOut_ ? 0.0 : context_.config.magazine.slideTravel; }
    // The tool in the spindle: what the magazine's spindle holds, else what the controller believes
    // (#1300 on the M350, the tool M85 stored on a FANUC). Asked before every block: inline.
    int spindleTool() const {
        const int believed = context_.config.dialect->id == gcode::DialectId::M350
                                 ? saturatingInt(context_.config.parameters.get(param::kCurrentTool))
                                 : context_.pmcSpindleTool;
        if (!device_) {
            return believed;
        }
        // what the spindle really holds; a virtual tool (above the magazine) was put in by hand,
        // which the magazine does not see
        const int held = device_->spindleTool();
        return held == 0 && believed > device_->pocketCount() ? believed : held;
    }
    // Why the machine's PMC refuses T`tool` at the T word, before anything moves (an umbrella
    // carousel's ladder checks the T code against its pockets); nullopt when it takes it.
    std::optional<Message> refusedTool(int tool) const;
    // Feeds one machine event to the device; throws a `crash` or `sensor_timeout` MacroError.
    void onMachineEvent(const machine::MachineEvent& event);
    // A straight move from `from` to `to` the device need not be told of: far from a linear rack
    // with nothing engaged in it and no move under way to take again (LinearRack::ignores).
    bool ignores(const machine::Axes& from, const machine::Axes& to) const;
    // The move under way stopped short at `position` (Magazine::stoppedAt).
    void moveStoppedAt(const machine::Axes& position);
    // "IN11 (tool released)": the IO page's function on the pin, else the magazine's own sensor;
    // its Chinese name with `chinese`.
    std::string describeInput(int pin, bool chinese = false) const;

private:
    struct Sensor {
        int pin = 0; // 0: not wired
        int activeLevel = 1;
    };
    struct DrawbarWiring {
        int output = 0;
        int releaseLevel = 1;
        Sensor released;
        Sensor clamped;
        double seconds = 0.15; // the clamp cylinder's stroke
    };

    void buildRack();
    void buildMultiHead();
    void buildDisc();
    void buildCarousel();
    void wireDrawbar();
    template <class Device> Device* install(std::unique_ptr<Device> device) {
        Device* installed = device.get();
        device_ = std::move(device);
        return installed;
    }
    std::optional<Message> output(int port, int level, double now);
    void driveSensor(const Sensor& sensor, bool active, double at);
    void driveInPosition(double now, double seconds);
    Eigen::Vector3d noseAt(const machine::Axes& position) const;
    // a FANUC carousel's PMC (UmbrellaPmc.cpp)
    void answerPmc(int code);
    void awaitSensor(int pin, int level, int mCode);

    Context context_;
    std::unique_ptr<devices::Magazine> device_;
    devices::LinearRack* rack_ = nullptr;           // device_ when it is a linear rack
    devices::ServoDisc* disc_ = nullptr;            // device_ when it is a servo disc
    devices::UmbrellaCarousel* carousel_ = nullptr; // device_ when it is an umbrella carousel
    devices::MultiHead* multiHead_ = nullptr;       // device_ when it is a multi-process machine
    DrawbarWiring drawbar_;
    bool slideOut_ = false; // a gantry rack's slide (output of param 753)
};

} // namespace m350::controller
