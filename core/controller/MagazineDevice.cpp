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
        Eigen::Vector3d at(p.get(kPocketX + k - 1), p.get(kPocketY + k - 1), p.get(kPocketZ + k - 1));
        if (at.isZero()) {
            break; // no position set: the rack ends here, whatever param 801 says
        }
        g.pockets.push_back(at);
        tools.push_back(k == inSpindle ? 0 : k); // every tool has its own pocket
    }
    rack_.emplace(std::move(g), std::move(tools), inSpindle >= 1 && inSpindle <= capacity ? inSpindle : 0);
}

void Controller::checkMagazine(const machine::MachineEvent& event) {
    using Type = machine::MachineEvent::Type;
    std::optional<std::string> crash;
    switch (event.type) {
    case Type::Rapid:
    case Type::Feed:
    case Type::Arc:
        crash = rack_->move(event.from.head<3>(), event.to.head<3>(), event.type == Type::Rapid,
                            machine_.spindleTurning());
        break;
    case Type::Io: {
        config::PortAssignment drawbar = config::portAssignment(config_.parameters, kDrawbarOutput);
        if (event.port > 0 && drawbar.wired() && event.port == drawbar.pin) {
            crash = rack_->drawbar(event.level == drawbar.activeLevel, machine_.position().head<3>());
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
