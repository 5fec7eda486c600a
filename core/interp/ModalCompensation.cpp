// G41/G42 cutter radius compensation in the XY plane (G17): programmed moves go through the
// CutterCompensation engine, which answers with tool-center segments one move later (it must see
// the next move to shape the corner). Meanwhile the program's own position runs ahead of the
// machine's, so targets are computed from the programmed position.
#include "core/interp/ModalInterpreter.h"

#include "core/machine/ArcGeometry.h"

namespace m350::interp {

using macro::MacroError;

bool ModalInterpreter::compensating() const {
    return compensation_.side() != CompensationSide::Off || compensation_.hasPending();
}

machine::Axes ModalInterpreter::basePosition() const {
    return compensating() ? programmed_ : machine_.position();
}

double ModalInterpreter::compensationRadius() const {
    return toolOffsets_.get(state_.radiusOffset) * axisUnit(0);
}

void ModalInterpreter::compensatedMove(const machine::Axes& target, const Words& words) {
    if (state_.group(2) != 17) {
        throw MacroError{AlarmCode::InvalidWord, "cutter compensation (G41/G42) works in the G17 XY plane only",
                         motionColumn(words)};
    }
    if (!compensating()) {
        programmed_ = machine_.position(); // entering: the program and the machine agree
    }
    machine::Axes offset = workOffset();
    Eigen::Vector2d from = (programmed_ - offset).head<2>();
    Eigen::Vector2d to = (target - offset).head<2>();
    PathSegment segment = PathSegment::line(from, to);
    if (state_.group(1) == 2 || state_.group(1) == 3) {
        Eigen::Vector2d center = from;
        if (const macro::WordValue* i = words.find('I')) {
            center.x() += i->value * axisUnit(0);
        }
        if (const macro::WordValue* j = words.find('J')) {
            center.y() += j->value * axisUnit(1);
        }
        if (words.find('R')) {
            throw MacroError{AlarmCode::InvalidWord, "write arcs under cutter compensation with I and J, not R",
                             motionColumn(words)};
        }
        segment = PathSegment::arc(from, to, center, state_.group(1) == 2);
    }
    CompensationSide side = state_.group(7) == 41   ? CompensationSide::Left
                            : state_.group(7) == 42 ? CompensationSide::Right
                                                    : CompensationSide::Off;
    auto result = compensation_.feed(segment, side, compensationRadius());
    if (auto* error = std::get_if<CompensationError>(&result)) {
        throw MacroError{AlarmCode::InvalidWord, error->message, motionColumn(words)};
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

// Tool-center segments are in work XY; Z, A and B go to where the move that produced them ends.
void ModalInterpreter::emitToolPath(const std::vector<PathSegment>& segments) {
    machine::Axes offset = workOffset();
    for (const PathSegment& s : segments) {
        machine::Axes end = pendingHeight_;
        end.head<2>() = s.end + offset.head<2>();
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
        spec.plane = machine::Plane::XY;
        spec.clockwise = s.clockwise;
        Eigen::Vector2d center = s.center + offset.head<2>() - spec.start.head<2>();
        spec.centerOffset = Eigen::Vector3d(center.x(), center.y(), 0.0);
        auto arc = machine::makeArc(spec);
        if (auto* error = std::get_if<machine::ArcError>(&arc)) {
            throw MacroError{AlarmCode::InvalidWord, "compensated arc: " + error->message, 0};
        }
        machine_.arc(std::get<machine::Arc>(arc), feedRate(0));
    }
}

} // namespace m350::interp
