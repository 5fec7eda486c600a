#include "core/controller/ContinueRemainder.h"

#include "core/machine/ArcGeometry.h"

#include <variant>

namespace m350::controller {

void continueRemainder(machine::SimulatedMachine& simulated, const machine::SimulatedMachine::Remainder& rest) {
    using Kind = machine::SimulatedMachine::Remainder::Kind;
    switch (rest.kind) {
    case Kind::Rapid: simulated.rapid(rest.target); break;
    case Kind::Feed: simulated.feed(rest.target, rest.feed); break;
    case Kind::Dwell: simulated.dwell(rest.seconds); break;
    case Kind::Arc: {
        const machine::Arc& arc = *rest.arc;
        machine::ArcSpec spec;
        spec.start = simulated.position();
        spec.end = rest.target;
        spec.plane = arc.plane;
        spec.clockwise = arc.sweep < 0;
        spec.centerOffset = arc.center - spec.start.head<3>();
        auto remaining = machine::makeArc(spec);
        if (auto* done = std::get_if<machine::Arc>(&remaining)) {
            simulated.arc(*done, rest.feed);
        } else {
            simulated.feed(rest.target, rest.feed);
        }
        break;
    }
    case Kind::None: break;
    }
}

} // namespace m350::controller
