#include "core/controller/MagazineDriver.h"

#include "core/config/RackForks.h"

#include "core/common/Numeric.h"
#include "core/params/IoPorts.h"
#include "core/params/ParameterLimits.h"
#include "core/params/ParameterNumbers.h"
#include "core/devices/LinearRack.h"
#include "core/devices/MultiHead.h"
#include "core/devices/ServoDisc.h"
#include "core/devices/UmbrellaCarousel.h"
#include "core/interp/ModalInterpreter.h"
#include "core/machine/SimulatedMachine.h"
#include "core/macro/MacroError.h"

#include <algorithm>
#include <array>

namespace m350::controller {

using Device = config::MagazineConfig::Device;

namespace {

constexpr double kDefaultClampSeconds = 0.15;

// The tool param 800 (or --tool) puts in the spindle, when the magazine has a pocket for it.
int toolInMagazine(int tool, int pockets) {
    return tool >= 1 && tool <= pockets ? tool : 0;
}

// Every tool has its own pocket; the one in the spindle leaves its pocket empty.
std::vector<int> toolsInPockets(int pockets, int inSpindle) {
    std::vector<int> tools;
    for (int k = 1; k <= pockets; ++k) {
        tools.push_back(k == inSpindle ? 0 : k);
    }
    return tools;
}

} // namespace

MagazineDriver::MagazineDriver(Context context) : context_(std::move(context)) {}

MagazineDriver::~MagazineDriver() = default;

void MagazineDriver::build() {
    device_.reset();
    rack_ = nullptr;
    disc_ = nullptr;
    carousel_ = nullptr;
    multiHead_ = nullptr;
    wireDrawbar();
    switch (context_.config.magazine.device) {
    case Device::None: return;
    case Device::LinearRack: buildRack(); return;
    case Device::MultiHead: buildMultiHead(); return;
    case Device::ServoDisc: buildDisc(); return;
    case Device::Umbrella: buildCarousel(); return;
    }
}

void MagazineDriver::buildMultiHead() {
    const config::MagazineConfig& m = context_.config.magazine;
    const params::ParameterTable& p = context_.config.parameters;
    multiHead_ = install(std::make_unique<devices::MultiHead>(params::magazineCapacity(p),
                                                              p.get(param::kChangeZUp), m.tolerance,
                                                              saturatingInt(p.get(param::kCurrentTool))));
    // the head in use (param 800) was left down: its cylinder's output is on
    if (const int inUse = multiHead_->spindleTool(); inUse != 0) {
        params::PortAssignment cylinder = params::portAssignment(p, param::kMultiProcessOutput1 + 3 * (inUse - 1));
        if (cylinder.wired()) {
            context_.machine.setOutput(cylinder.pin, cylinder.activeLevel);
        }
    }
}

void MagazineDriver::buildDisc() {
    const config::MagazineConfig& m = context_.config.magazine;
    const params::ParameterTable& p = context_.config.parameters;
    devices::ServoDisc::Geometry g;
    g.station = m.station ? Eigen::Vector3d((*m.station)[0], (*m.station)[1], (*m.station)[2])
                          : Eigen::Vector3d(p.get(param::kChangeFrontX), p.get(param::kChangeFrontY), p.get(param::kChangeZDown));
    g.pockets = std::clamp(saturatingInt(p.get(param::kMagazineCapacity)), 1, 20);
    g.forkDepth = m.forkDepth;
    g.tolerance = m.tolerance;
    g.secondsPerPocket = m.secondsPerPocket;
    g.settleSeconds = m.settleSeconds;
    const int inSpindle = toolInMagazine(saturatingInt(p.get(param::kCurrentTool)), g.pockets);
    disc_ = install(std::make_unique<devices::ServoDisc>(g, toolsInPockets(g.pockets, inSpindle), inSpindle,
                                                         inSpindle != 0 ? inSpindle : 1));
    context_.machine.presetInput(m.inPositionInput, 1);
}

void MagazineDriver::buildCarousel() {
    const config::MagazineConfig& m = context_.config.magazine;
    const auto point = [this](int n) {
        auto it = context_.config.referencePoints.find(n);
        return it == context_.config.referencePoints.end() ? std::array<double, 5>{} : it->second;
    };
    devices::UmbrellaCarousel::Geometry g;
    g.changeX = m.changeXYGiven ? m.changeX : point(3)[0];
    g.changeY = m.changeXYGiven ? m.changeY : point(3)[1];
    g.gripZ = point(3)[2];
    g.clearZ = point(2)[2];
    g.pockets = m.pockets;
    g.tolerance = m.tolerance;
    g.secondsPerPocket = m.secondsPerPocket;
    g.slideSeconds = m.slideSeconds;
    const int inSpindle = toolInMagazine(context_.pmcSpindleTool, g.pockets);
    carousel_ = install(std::make_unique<devices::UmbrellaCarousel>(g, toolsInPockets(g.pockets, inSpindle), inSpindle,
                                                                    inSpindle != 0 ? inSpindle : 1));
    context_.machine.presetInput(m.inPositionInput, 1);
    context_.machine.presetInput(m.awayInput, 1);
    context_.machine.presetInput(m.atSpindleInput, 0);
}

void MagazineDriver::buildRack() {
    const params::ParameterTable& p = context_.config.parameters;
    const config::MagazineConfig& m = context_.config.magazine;
    devices::LinearRack::Geometry g;
    g.loading = m.topLoading ? devices::LinearRack::Loading::Top : devices::LinearRack::Loading::Side;
    g.openingY = m.openingY;
    g.forkDepth = m.forkDepth;
    g.tolerance = m.tolerance;
    g.pockets = config::rackForks(m, p);
    slideOut_ = false;
    const int pockets = static_cast<int>(g.pockets.size());
    const int spindle = toolInMagazine(saturatingInt(p.get(param::kCurrentTool)), pockets);
    rack_ = install(std::make_unique<devices::LinearRack>(std::move(g), toolsInPockets(pockets, spindle), spindle));
}

// The drawbar and its clamp cylinder's sensors: the IO page's triples on the M350, the magazine's
// wiring on a FANUC. The cylinder takes param 814 (when set above its default of 1 ms) or
// [magazine] clamp_ms, else 150 ms, to reach either end.
void MagazineDriver::wireDrawbar() {
    drawbar_ = DrawbarWiring{};
    const config::MagazineConfig& m = context_.config.magazine;
    if (!m.present()) {
        return;
    }
    if (context_.config.dialect->id == gcode::DialectId::M350) {
        const params::ParameterTable& p = context_.config.parameters;
        params::PortAssignment out = params::portAssignment(p, param::kDrawbarOutput);
        if (out.wired()) {
            drawbar_.output = out.pin;
            drawbar_.releaseLevel = out.activeLevel;
        }
        if (auto released = params::wiredInput(p, param::kToolReleasedInput)) {
            drawbar_.released = {released->pin, released->activeLevel};
        }
        if (auto clamped = params::wiredInput(p, param::kToolClampedInput)) {
            drawbar_.clamped = {clamped->pin, clamped->activeLevel};
        }
        const double lockDelay = p.get(param::kSpindleLockDelay) / 1000.0;
        drawbar_.seconds = m.clampSeconds > 0.0 ? m.clampSeconds : lockDelay > 0.001 ? lockDelay : kDefaultClampSeconds;
    } else {
        drawbar_.output = m.drawbarOutput;
        drawbar_.released = {m.releasedInput, 1};
        drawbar_.clamped = {m.clampedInput, 1};
        drawbar_.seconds = m.clampSeconds > 0.0 ? m.clampSeconds : kDefaultClampSeconds;
    }
    // power-on: the tool is clamped
    for (const auto& [sensor, clampedMeansActive] : {std::pair{drawbar_.released, false}, std::pair{drawbar_.clamped, true}}) {
        if (sensor.pin > 0) {
            context_.machine.presetInput(sensor.pin, clampedMeansActive ? sensor.activeLevel : 1 - sensor.activeLevel);
        }
    }
}

// Where the spindle nose stands as the rack sees it. A rack on the gantry moves in Y with the
// spindle, so only its slide changes the Y between them.
Eigen::Vector3d MagazineDriver::noseAt(const machine::Axes& position) const {
    Eigen::Vector3d nose = position.head<3>();
    if (context_.config.magazine.onGantry) {
        nose.y() = slideOut_ ? 0.0 : context_.config.magazine.slideTravel;
    }
    return nose;
}

// "IN11 (tool released)": the IO page's function on the pin, else the magazine's own sensor.
std::string MagazineDriver::describeInput(int pin, bool chinese) const {
    if (params::inputOnPin(context_.config.parameters, pin) || !context_.config.magazine.present()) {
        return params::describeInput(context_.config.parameters, pin, chinese);
    }
    const config::MagazineConfig& m = context_.config.magazine;
    const char* what = pin == m.inPositionInput
                           ? (disc_ ? (chinese ? "刀盘到位" : "disc in position") : (chinese ? "刀库到位" : "carousel in position"))
                       : pin == m.atSpindleInput ? (chinese ? "刀库在主轴处" : "carousel at the spindle")
                       : pin == m.awayInput      ? (chinese ? "刀库已退回" : "carousel away")
                       : pin == m.releasedInput  ? (chinese ? "松刀到位" : "tool released")
                       : pin == m.clampedInput   ? (chinese ? "夹刀到位" : "tool clamped")
                                                 : nullptr;
    return what && pin > 0 ? params::inputName(pin) + " (" + what + ")" : params::inputName(pin);
}

void MagazineDriver::driveSensor(const Sensor& sensor, bool active, double at) {
    if (sensor.pin > 0) {
        context_.machine.driveInput(sensor.pin, active ? sensor.activeLevel : 1 - sensor.activeLevel, at);
        context_.inputSource[sensor.pin] = context_.source();
    }
}

// A disc or carousel turning from `now` for `seconds`: its in-position signal is off meanwhile.
void MagazineDriver::driveInPosition(double now, double seconds) {
    if (seconds > 0.0) {
        const Sensor inPosition{context_.config.magazine.inPositionInput, 1};
        driveSensor(inPosition, false, now);
        driveSensor(inPosition, true, now + seconds);
    }
}

bool MagazineDriver::ignores(const machine::Axes& from, const machine::Axes& to) const {
    if (!rack_) {
        return false;
    }
    if (context_.config.magazine.onGantry) {
        return rack_->ignores(noseAt(from), noseAt(to));
    }
    return rack_->ignores(from.head<3>(), to.head<3>());
}

void MagazineDriver::onMachineEvent(const machine::MachineEvent& event) {
    using Type = machine::MachineEvent::Type;
    std::optional<Message> crash;
    switch (event.type) {
    case Type::Rapid:
    case Type::Feed:
    case Type::Arc: {
        const Eigen::Vector3d from = noseAt(event.from);
        const Eigen::Vector3d to = noseAt(event.to);
        if (rack_ && rack_->passesFar(from, to)) {
            return;
        }
        crash = device_->move(from, to, event.type == Type::Rapid, context_.machine.spindleTurning(), event.start);
        break;
    }
    case Type::Io:
        if (event.port > 0) {
            crash = output(event.port, event.level, context_.machine.time());
        }
        break;
    case Type::Spindle:
        device_->spindle(context_.machine.spindleTurning(), event.spindle == machine::SpindleState::Orient);
        break;
    case Type::Auxiliary:
        if (carousel_) {
            answerPmc(event.port);
        }
        break;
    default: break;
    }
    if (crash) {
        throw macro::MacroError::of(AlarmCode::Crash, *crash);
    }
}

void MagazineDriver::moveStoppedAt(const machine::Axes& position) {
    if (device_) {
        device_->stoppedAt(noseAt(position));
    }
}

std::optional<Message> MagazineDriver::output(int port, int level, double now) {
    const Eigen::Vector3d nose = noseAt(context_.machine.position());
    if (port == drawbar_.output) {
        const bool released = level == drawbar_.releaseLevel;
        driveSensor(drawbar_.released, released, now + drawbar_.seconds);
        driveSensor(drawbar_.clamped, !released, now + drawbar_.seconds);
        return device_->drawbar(released, nose);
    }
    const config::MagazineConfig& m = context_.config.magazine;
    if (m.onGantry) {
        params::PortAssignment slide = params::portAssignment(context_.config.parameters, param::kMagazineSlideOutput);
        if (slide.wired() && port == slide.pin) {
            // the slide carries the forks to the spindle or away: a move along Y between them
            slideOut_ = level == slide.activeLevel;
            return device_->move(nose, noseAt(context_.machine.position()), false, context_.machine.spindleTurning(), now);
        }
    }
    if (disc_ && port == m.strobeOutput && level == 1) {
        int pocket = 0;
        for (std::size_t bit = 0; bit < m.selectOutputs.size(); ++bit) {
            pocket |= context_.machine.output(m.selectOutputs[bit]) << bit;
        }
        devices::ServoDisc::Turn turn = disc_->turnTo(pocket, now, nose);
        if (!turn.crash) {
            driveInPosition(now, turn.seconds);
        }
        return turn.crash;
    }
    for (int head = 1; multiHead_ && head <= multiHead_->pocketCount(); ++head) {
        params::PortAssignment cylinder =
            params::portAssignment(context_.config.parameters, param::kMultiProcessOutput1 + 3 * (head - 1));
        if (cylinder.wired() && port == cylinder.pin) {
            return multiHead_->cylinder(head, level == cylinder.activeLevel, nose);
        }
    }
    if (carousel_ && port == m.slideOutput) {
        devices::UmbrellaCarousel::Action slide = carousel_->slide(level == 1, nose, now);
        if (slide.seconds > 0.0) {
            driveSensor({m.awayInput, 1}, false, now);
            driveSensor({m.atSpindleInput, 1}, false, now);
            driveSensor({level == 1 ? m.atSpindleInput : m.awayInput, 1}, true, now + slide.seconds);
        }
        return slide.crash;
    }
    return std::nullopt;
}

} // namespace m350::controller
