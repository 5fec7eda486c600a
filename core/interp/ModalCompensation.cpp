// G41/G42 cutter radius compensation in the plane of G17 (XY), G18 (ZX) or G19 (YZ): programmed
// moves go through the CutterCompensation engine, which answers with tool-center segments one move
// later (it must see the next move to shape the corner). Meanwhile the program's own position runs
// ahead of the machine's, so targets are computed from the programmed position. The engine works
// in 2-D (u, v); each plane names its axes so that u x v is the plane's normal (+Z, +Y, +X), which
// keeps G2 clockwise and G41 on the left as seen from that normal.
#include "core/interp/ModalInterpreter.h"

#include "core/machine/ArcGeometry.h"

namespace m350::interp {

using macro::MacroError;

double ModalInterpreter::compensationRadius() const {
    return tools_.radiusOffset(state_.radiusOffset) * axisUnit(0);
}

ModalInterpreter::PlaneAxes ModalInterpreter::planeAxes(int planeCode) {
    switch (planeCode) {
    case 18: return {2, 0, machine::Plane::ZX};
    case 19: return {1, 2, machine::Plane::YZ};
    default: return {0, 1, machine::Plane::XY};
    }
}

Eigen::Vector2d ModalInterpreter::inPlane(const machine::Axes& p) const {
    return {p(compensationPlane_.u), p(compensationPlane_.v)};
}

void ModalInterpreter::compensatedMove(const machine::Axes& target, const Words& words) {
    if (!compensating()) {
        programmed_ = machine_.position(); // entering: the program and the machine agree
        compensationPlane_ = planeAxes(state_.group(2));
    } else if (planeAxes(state_.group(2)).plane != compensationPlane_.plane) {
        throw MacroError::of(AlarmCode::InvalidWord, message("compensation_plane_changed"), motionColumn(words));
    }
    const int u = compensationPlane_.u;
    const int v = compensationPlane_.v;
    machine::Axes offset = workOffset();
    Eigen::Vector2d from = inPlane(programmed_ - offset);
    Eigen::Vector2d to = inPlane(target - offset);
    PathSegment segment = PathSegment::line(from, to);
    if (state_.group(1) == 2 || state_.group(1) == 3) {
        static constexpr std::array<char, 3> kCenterLetter{'I', 'J', 'K'};
        Eigen::Vector3d toCenter = Eigen::Vector3d::Zero();
        if (const macro::WordValue* c = words.find(kCenterLetter[static_cast<std::size_t>(u)])) {
            toCenter(u) = c->value * axisUnit(u);
        }
        if (const macro::WordValue* c = words.find(kCenterLetter[static_cast<std::size_t>(v)])) {
            toCenter(v) = c->value * axisUnit(v);
        }
        if (state_.rotating()) {
            state_.rotation.turn(toCenter); // G68 turns the plane's I J K with the path
        }
        const Eigen::Vector2d center = from + Eigen::Vector2d(toCenter(u), toCenter(v));
        if (words.find('R')) {
            throw MacroError::of(AlarmCode::InvalidWord,
                                 message("compensation_arc_r", {std::string(1, kCenterLetter[static_cast<std::size_t>(u)]),
                                                                std::string(1, kCenterLetter[static_cast<std::size_t>(v)])}),
                                 motionColumn(words));
        }
        segment = PathSegment::arc(from, to, center, state_.group(1) == 2);
    }
    CompensationSide side = state_.group(7) == 41   ? CompensationSide::Left
                            : state_.group(7) == 42 ? CompensationSide::Right
                                                    : CompensationSide::Off;
    auto result = compensation_.feed(segment, side, compensationRadius());
    if (auto* error = std::get_if<CompensationError>(&result)) {
        throw MacroError::of(AlarmCode::InvalidWord, error->message, motionColumn(words));
    }
    emitToolPath(std::get<std::vector<PathSegment>>(result));
    pendingMode_ = state_.group(1);
    pendingHeight_ = target;
    programmed_ = target;
    if (side == CompensationSide::Off) {
        emitToolPath(compensation_.flush()); // G40 move: the exit is final
    }
}

void ModalInterpreter::flushCompensation() {
    if (compensation_.hasPending()) {
        emitToolPath(compensation_.flush());
    }
}

// Tool-center segments are in the plane's work coordinates; the other axes go to where the move
// that produced them ends.
void ModalInterpreter::emitToolPath(const std::vector<PathSegment>& segments) {
    machine::Axes offset = workOffset();
    const int u = compensationPlane_.u;
    const int v = compensationPlane_.v;
    for (const PathSegment& s : segments) {
        machine::Axes end = pendingHeight_;
        end(u) = s.end.x() + offset(u);
        end(v) = s.end.y() + offset(v);
        checkSoftLimits(end, Words{});
        if (s.kind == PathSegment::Kind::Line) {
            if (pendingMode_ == 0) {
                machine_.rapid(end);
            } else {
                machine_.feed(end, feedRate(0));
            }
            continue;
        }
        machine::ArcSpec spec;
        spec.start = machine_.position();
        spec.end = end;
        spec.plane = compensationPlane_.plane;
        spec.clockwise = s.clockwise;
        Eigen::Vector3d center = Eigen::Vector3d::Zero();
        center(u) = s.center.x() + offset(u) - spec.start(u);
        center(v) = s.center.y() + offset(v) - spec.start(v);
        spec.centerOffset = center;
        auto arc = machine::makeArc(spec);
        if (auto* error = std::get_if<machine::ArcError>(&arc)) {
            throw MacroError::of(AlarmCode::InvalidWord, message("compensated_arc", {bilingual(error->message)}));
        }
        machine_.arc(std::get<machine::Arc>(arc), feedRate(0));
    }
}

} // namespace m350::interp
