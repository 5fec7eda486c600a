// The tool magazine as a device beside the machine: it sees every move of the spindle nose and
// every switch of the drawbar output, keeps track of the tools, and turns what the hardware would
// suffer into a `crash` alarm on the macro line that caused it.
#include "core/controller/Controller.h"

#include "core/common/Numeric.h"
#include "core/config/IoPorts.h"
#include "core/config/ParameterNumbers.h"
#include "core/macro/MacroError.h"

namespace m350::controller {

namespace param = config::param;

namespace {

constexpr int kPocketX = 830; // pocket k: X 830+k-1, Y 850+k-1, Z 870+k-1 (machine)
constexpr int kPocketY = 850;
constexpr int kPocketZ = 870;
constexpr int kDrawbarOutput = 750; // 刀具松开/锁紧输出 (M154/M155)
constexpr int kSlideOutput = 753;   // 刀库推出/收回输出 (M152/M153)

} // namespace

void Controller::buildMagazine() {
    rack_.reset();
    if (!config_.rack.present) {
        return;
    }
    const config::ParameterTable& p = config_.parameters;
    devices::LinearRack::Geometry g;
    g.loading = config_.rack.topLoading ? devices::LinearRack::Loading::Top : devices::LinearRack::Loading::Side;
    g.openingY = config_.rack.openingY;
    g.forkDepth = config_.rack.forkDepth;
    g.tolerance = config_.rack.tolerance;
    const int capacity = std::clamp(saturatingInt(p.get(param::kMagazineCapacity)), 0, 20);
    const int inSpindle = saturatingInt(p.get(param::kCurrentTool));
    std::vector<int> tools;
    for (int k = 1; k <= capacity; ++k) {
        // On the gantry the forks stand beside the spindle in Y: Y 0 is "slide out", the travel "in".
        double y = config_.rack.onGantry ? 0.0 : p.get(kPocketY + k - 1);
        Eigen::Vector3d at(p.get(kPocketX + k - 1), y, p.get(kPocketZ + k - 1));
        if (at.isZero() || (config_.rack.onGantry && at.x() == 0.0 && at.z() == 0.0)) {
            break; // no position set: the rack ends here, whatever param 801 says
        }
        g.pockets.push_back(at);
        tools.push_back(k == inSpindle ? 0 : k); // every tool has its own pocket
    }
    slideOut_ = false;
    const int spindle = inSpindle >= 1 && inSpindle <= static_cast<int>(tools.size()) ? inSpindle : 0;
    rack_.emplace(std::move(g), std::move(tools), spindle);
}

// Where the spindle nose stands as the rack sees it. A rack on the gantry moves in Y with the
// spindle, so only its slide changes the Y between them.
Eigen::Vector3d Controller::noseForRack(const machine::Axes& position) const {
    Eigen::Vector3d nose = position.head<3>();
    if (config_.rack.onGantry) {
        nose.y() = slideOut_ ? 0.0 : config_.rack.slideTravel;
    }
    return nose;
}

void Controller::checkMagazine(const machine::MachineEvent& event) {
    using Type = machine::MachineEvent::Type;
    std::optional<std::string> crash;
    switch (event.type) {
    case Type::Rapid:
    case Type::Feed:
    case Type::Arc:
        crash = rack_->move(noseForRack(event.from), noseForRack(event.to), event.type == Type::Rapid,
                            machine_.spindleTurning());
        break;
    case Type::Io: {
        config::PortAssignment drawbar = config::portAssignment(config_.parameters, kDrawbarOutput);
        config::PortAssignment slide = config::portAssignment(config_.parameters, kSlideOutput);
        if (event.port > 0 && drawbar.wired() && event.port == drawbar.pin) {
            crash = rack_->drawbar(event.level == drawbar.activeLevel, noseForRack(machine_.position()));
        } else if (config_.rack.onGantry && event.port > 0 && slide.wired() && event.port == slide.pin) {
            // the slide carries the forks to the spindle or away: a move along Y between them
            const Eigen::Vector3d from = noseForRack(machine_.position());
            slideOut_ = event.level == slide.activeLevel;
            crash = rack_->move(from, noseForRack(machine_.position()), false, machine_.spindleTurning());
        }
        break;
    }
    default: break;
    }
    if (crash) {
        throw macro::MacroError{AlarmCode::Crash, *crash, 0};
    }
}

} // namespace m350::controller
