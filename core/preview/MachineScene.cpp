// The machine view's scene, built from what the controller's parts know at one moment: the
// parameters and the machine folder, the tool data, the magazine device and the offsets in force.
// Where each part comes from, and the choices no parameter makes, are in README.md ("The machine
// view (图形显示): what it draws").
#include "core/preview/MachineScene.h"

#include "core/controller/Controller.h"
#include "core/devices/LinearRack.h"
#include "core/devices/MultiHead.h"
#include "core/devices/ServoDisc.h"
#include "core/devices/UmbrellaCarousel.h"
#include "core/params/IoPorts.h"
#include "core/params/ParameterNumbers.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace m350::preview {

namespace {

using Device = config::MagazineConfig::Device;

// Parameters 161-170 at ±9999 (the factory's values) limit nothing.
constexpr double kNoLimit = 9998.0;
// A box derived from the folder's positions reaches this far past them in X and Y, and below the
// lowest of them by the longest tool and this (no parameter says the machine's travel).
constexpr double kTravelMargin = 50.0;
// The table's top lies this far below the lowest the spindle nose may go.
constexpr double kTableGap = 10.0;
// A disc's or carousel's pockets stand this far apart on their circle (their pitch is no
// parameter), and an umbrella carousel slides this far from the spindle to stand away.
constexpr double kPocketPitch = 100.0;
constexpr double kMinimumRadius = 100.0;
constexpr double kUmbrellaStroke = 150.0;

ScenePoint toScenePoint(const Eigen::Vector3d& v) {
    return {v.x(), v.y(), v.z()};
}

class SceneBuilder {
public:
    explicit SceneBuilder(const controller::Controller& controller)
        : controller_(controller), config_(controller.machineConfig()), p_(config_.parameters),
          m350_(config_.dialect->id == gcode::DialectId::M350) {}

    MachineScene build() {
        travel();
        spindle();
        magazine();
        setters();
        levels();
        fallen();
        workZero(); // after the tools: the spindle tool's length places it
        reachWorkZero();
        return std::move(scene_);
    }

private:
    // The length and diameter a tool is drawn with (README: the order). M350: a Z offset (params
    // 930-945 / 973-992, tool.tbl's Z: the nose's machine Z when the tool trips the fixed setter)
    // less the setter's top ([tool_setter] top: that Z for a zero-length tool); FANUC: the offset
    // memory's length (tool.tbl's Z, + H wear on memory C). The tool table's D for the diameter.
    // What the controller does not know, the simulated world's tool ([tools] length / diameter).
    SceneTool toolOf(int number) const {
        SceneTool tool;
        tool.number = number;
        const tools::ToolData& data = controller_.toolData();
        if (m350_) {
            const double z = data.z(number);
            if (z != 0.0 && z - config_.setterTop > 0.0) {
                tool.length = z - config_.setterTop;
            }
        } else if (data.validOffsetNumber(number)) {
            tool.length = std::max(0.0, data.lengthOffset(number));
        }
        tool.diameter = std::max(0.0, data.diameter(number).value_or(0.0));
        const machine::ToolWorld& world = controller_.toolBreakage().world();
        if (tool.length == 0.0) {
            tool.length = std::max(0.0, world.nominalLength(number));
        }
        if (tool.diameter == 0.0) {
            tool.diameter = std::max(0.0, world.diameter(number).value_or(0.0));
        }
        return tool;
    }
    void addTool(int number) {
        if (number > 0 && !scene_.tools.count(number)) {
            scene_.tools.emplace(number, toolOf(number));
        }
    }

    // Params 161-170 when param 155 turns the soft limits on and they limit the axis; otherwise
    // the box around every machine position the folder names, grown by kTravelMargin.
    void travel() {
        Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
        Eigen::Vector3d high = -low;
        auto include = [&](double x, double y, double z) {
            const Eigen::Vector3d v(x, y, z);
            low = low.cwiseMin(v);
            high = high.cwiseMax(v);
        };
        include(0.0, 0.0, 0.0); // machine zero
        if (m350_) {
            include(p_.get(param::kHomePositionX), p_.get(param::kHomePositionX + 1), p_.get(param::kHomePositionX + 2));
        }
        for (const auto& [number, at] : config_.referencePoints) {
            include(at[0], at[1], at[2]);
        }
        if (fixedSetterShown()) {
            include(p_.get(param::kFixedSetterX), p_.get(param::kFixedSetterX + 1), config_.setterTop);
        }
        if (const devices::LinearRack* rack = controller_.magazine().rack()) {
            for (const Eigen::Vector3d& at : rack->geometry().pockets) {
                include(at.x(), config_.magazine.onGantry ? 0.0 : at.y(), at.z());
            }
        }
        if (const devices::ServoDisc* disc = controller_.magazine().disc()) {
            const Eigen::Vector3d& at = disc->geometry().station;
            include(at.x(), at.y(), at.z());
        }
        if (const devices::UmbrellaCarousel* carousel = controller_.magazine().carousel()) {
            const auto& g = carousel->geometry();
            include(g.changeX, g.changeY, g.gripZ);
        }
        double longest = 0.0;
        for (double length : config_.toolLengths) {
            longest = std::max(longest, length);
        }
        low.head<2>().array() -= kTravelMargin;
        high.head<2>().array() += kTravelMargin;
        low.z() -= std::max(longest, kTravelMargin) + kTravelMargin;

        const bool limitsOn = p_.get(param::kSoftLimitsEnabled) != 0.0;
        int limited = 0;
        for (int axis = 0; axis < 3; ++axis) {
            const double lo = p_.get(param::kSoftLimitNegativeX + axis);
            const double hi = p_.get(param::kSoftLimitPositiveX + axis);
            if (limitsOn && std::abs(lo) < kNoLimit && std::abs(hi) < kNoLimit && lo < hi) {
                low(axis) = lo;
                high(axis) = hi;
                ++limited;
            }
        }
        scene_.travel = {toScenePoint(low), toScenePoint(high)};
        scene_.travelFromSoftLimits = limited == 3;
        scene_.table = {{low.x(), low.y(), low.z() - kTableGap - 40.0}, {high.x(), high.y(), low.z() - kTableGap}};
    }

    void spindle() {
        scene_.spindleTool = controller_.magazine().spindleTool();
        addTool(scene_.spindleTool);
    }

    void magazine() {
        const controller::MagazineDriver& driver = controller_.magazine();
        SceneMagazine& out = scene_.magazine;
        if (const devices::LinearRack* rack = driver.rack()) {
            out.kind = SceneMagazine::Kind::LinearRack;
            out.topLoading = rack->geometry().loading == devices::LinearRack::Loading::Top;
            out.openingY = rack->geometry().openingY;
            out.onGantry = config_.magazine.onGantry;
            // on the gantry the forks stand beside the spindle in Y, as MagazineDriver::noseAt has it
            const double forksY = controller_.displayPosition()(1) - driver.gantryNoseY();
            int k = 0;
            for (const Eigen::Vector3d& at : rack->geometry().pockets) {
                ++k;
                ScenePocket pocket{k, toScenePoint(at), rack->pocketTool(k), false};
                if (out.onGantry) {
                    pocket.at.y = forksY;
                }
                out.pockets.push_back(pocket);
            }
        } else if (const devices::ServoDisc* disc = driver.disc()) {
            out.kind = SceneMagazine::Kind::ServoDisc;
            const Eigen::Vector3d& station = disc->geometry().station;
            ring(out, station, outward(station), disc->turnPosition(controller_.displayTime()), disc->pocketAtStation(),
                 [disc](int k) { return disc->pocketTool(k); });
        } else if (const devices::UmbrellaCarousel* carousel = driver.carousel()) {
            out.kind = SceneMagazine::Kind::Umbrella;
            const auto& g = carousel->geometry();
            out.slide = carousel->slidePosition(controller_.displayTime());
            // the carousel stands on the -X side: it comes in "向右靠近主轴" (to the right, toward
            // the spindle), M83 in the FANUC paper's O9001
            const Eigen::Vector3d direction(-1.0, 0.0, 0.0);
            const Eigen::Vector3d station =
                Eigen::Vector3d(g.changeX, g.changeY, g.gripZ) + direction * (1.0 - out.slide) * kUmbrellaStroke;
            ring(out, station, direction, carousel->turnPosition(controller_.displayTime()), carousel->pocketAtSpindle(),
                 [carousel](int k) { return carousel->pocketTool(k); });
        } else if (const devices::MultiHead* heads = driver.multiHead()) {
            out.kind = SceneMagazine::Kind::MultiHead;
            out.followsSpindle = true;
            for (int k = 1; k <= heads->pocketCount(); ++k) {
                // a head's X Y offset from the spindle nose: params 890+ / 910+ (as O502 adds them)
                const ScenePoint offset{p_.get(param::kToolXOffsetFirst + k - 1), p_.get(param::kToolYOffsetFirst + k - 1), 0.0};
                out.pockets.push_back({k, offset, k, heads->down(k)});
            }
        }
        for (const ScenePocket& pocket : out.pockets) {
            addTool(pocket.tool);
        }
    }

    // The direction in XY from the travel's middle to `station`, where a disc stands beside the
    // table; +Y when the station is the middle.
    Eigen::Vector3d outward(const Eigen::Vector3d& station) const {
        const Eigen::Vector3d middle((scene_.travel.low.x + scene_.travel.high.x) / 2.0,
                                     (scene_.travel.low.y + scene_.travel.high.y) / 2.0, station.z());
        const Eigen::Vector3d d = station - middle;
        return d.norm() > 1e-6 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d(0.0, 1.0, 0.0);
    }

    // A disc's or carousel's pockets on their circle: `turn` (fractional while it turns) faces the
    // station, the centre lies `direction` from the station, pocket numbers go counter-clockwise.
    template <class ToolIn>
    void ring(SceneMagazine& out, const Eigen::Vector3d& station, const Eigen::Vector3d& direction, double turn,
              int atStation, ToolIn toolIn) {
        const int n = controller_.magazine().device()->pocketCount();
        out.radius = std::max(kMinimumRadius, n * kPocketPitch / (2.0 * std::numbers::pi));
        const Eigen::Vector3d centre = station + direction * out.radius;
        out.centre = toScenePoint(centre);
        const double facing = std::atan2(-direction.y(), -direction.x());
        for (int k = 1; k <= n; ++k) {
            const double angle = facing + (k - turn) * 2.0 * std::numbers::pi / n;
            const Eigen::Vector3d at = centre + out.radius * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
            out.pockets.push_back({k, toScenePoint(at), toolIn(k), k == atStation});
        }
    }

    bool fixedSetterShown() const {
        return params::wiredInput(p_, param::kFixedSetterInput).has_value() &&
               (!m350_ || p_.get(param::kFixedSetterValid) != 0.0);
    }

    void setters() {
        if (fixedSetterShown()) {
            scene_.setters.push_back({SceneSetter::Kind::Fixed, p_.get(param::kFixedSetterX),
                                      p_.get(param::kFixedSetterX + 1), config_.setterTop, config_.setterRadius});
        }
    }

    void level(const char* id, double z, std::vector<std::string> arguments = {}) {
        scene_.levels.push_back({message(id, std::move(arguments)), z});
    }

    // The Z levels the machine's tool change and setting use (README: which macro uses which).
    void levels() {
        const controller::MagazineDriver& driver = controller_.magazine();
        if (m350_ && driver.device()) {
            level("scene_level_change_up", p_.get(param::kChangeZUp));
            const double down = p_.get(param::kChangeZDown);
            if (driver.disc() || (down != 0.0 && down != p_.get(param::kChangeZUp))) {
                level("scene_level_change_down", down);
            }
        }
        if (const devices::LinearRack* rack = driver.rack()) {
            // each height the pockets stand at, with the pockets at it: "1-10", "3"
            std::map<double, std::vector<int>> heights;
            int k = 0;
            for (const Eigen::Vector3d& at : rack->geometry().pockets) {
                heights[at.z()].push_back(++k);
            }
            for (const auto& [z, pockets] : heights) {
                level("scene_level_pocket", z, {pocketRange(pockets)});
            }
        }
        if (const devices::UmbrellaCarousel* carousel = driver.carousel()) {
            level("scene_level_carousel_clear", carousel->geometry().clearZ);
            level("scene_level_carousel_grip", carousel->geometry().gripZ);
        }
        if (m350_ && (p_.get(param::kVirtualTools) != 0.0 || !driver.device())) {
            level("scene_level_manual_change", p_.get(param::kManualChangeX + 2));
        }
        if (fixedSetterShown()) {
            level("scene_level_setter_safe", p_.get(param::kSetterSafeZ));
            level("scene_level_setter_start", p_.get(param::kFixedSetterX + 2));
        }
    }

    static std::string pocketRange(const std::vector<int>& pockets) {
        bool consecutive = true;
        for (std::size_t i = 1; i < pockets.size(); ++i) {
            consecutive = consecutive && pockets[i] == pockets[i - 1] + 1;
        }
        if (pockets.size() > 1 && consecutive) {
            return std::to_string(pockets.front()) + "-" + std::to_string(pockets.back());
        }
        std::string out;
        for (int k : pockets) {
            out += (out.empty() ? "" : ",") + std::to_string(k);
        }
        return out;
    }

    void fallen() {
        const devices::Magazine* device = controller_.magazine().device();
        if (!device) {
            return;
        }
        for (const devices::FallenTool& tool : device->droppedTools()) {
            scene_.fallen.push_back({tool.tool, {tool.at.x(), tool.at.y(), scene_.table.high.z}});
            addTool(tool.tool);
        }
    }

    // Where the tip of the spindle's tool stands at the active system's zero: the offsets in force
    // (interp's work offset, as panelStatus applies it) less the tool's length; the floating setter
    // lies on the work there.
    void workZero() {
        const interp::ModalInterpreter& interp = controller_.interpreter();
        const machine::Axes& offset = interp.workOffset();
        const SceneTool* tool = scene_.tool(scene_.spindleTool);
        scene_.workZero = {offset(0), offset(1), offset(2) - (tool ? tool->length : 0.0)};
        scene_.workSystem = controller::workSystemName(interp.activeSlot());
        if (config_.floatingSetterTop && params::wiredInput(p_, param::kFloatingSetterInput) &&
            (!m350_ || p_.get(param::kFloatingSetterValid) != 0.0)) {
            scene_.setters.push_back({SceneSetter::Kind::Floating, scene_.workZero.x, scene_.workZero.y,
                                      *config_.floatingSetterTop, 0.0});
        }
    }

    // A travel no soft limit gives reaches the work zero too: the work lies on the table there.
    void reachWorkZero() {
        if (scene_.travelFromSoftLimits) {
            return;
        }
        const ScenePoint& zero = scene_.workZero;
        for (SceneBox* box : {&scene_.travel, &scene_.table}) {
            box->low.x = std::min(box->low.x, zero.x - kTravelMargin);
            box->low.y = std::min(box->low.y, zero.y - kTravelMargin);
            box->high.x = std::max(box->high.x, zero.x + kTravelMargin);
            box->high.y = std::max(box->high.y, zero.y + kTravelMargin);
        }
    }

    const controller::Controller& controller_;
    const config::MachineConfig& config_;
    const params::ParameterTable& p_;
    bool m350_;
    MachineScene scene_;
};

} // namespace

MachineScene buildScene(const controller::Controller& controller) {
    return SceneBuilder(controller).build();
}

std::shared_ptr<const MachineScene> sceneSince(std::shared_ptr<const MachineScene> last,
                                               const controller::Controller& controller) {
    MachineScene now = buildScene(controller);
    if (last && *last == now) {
        return last;
    }
    return std::make_shared<const MachineScene>(std::move(now));
}

} // namespace m350::preview
