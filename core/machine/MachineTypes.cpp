#include "core/machine/MachineTypes.h"

namespace m350::machine {

std::string_view spindleStateName(SpindleState state) {
    switch (state) {
    case SpindleState::Stop: return "STOP";
    case SpindleState::Forward: return "FWD";
    case SpindleState::Reverse: return "REV";
    case SpindleState::Jog: return "JOG";
    case SpindleState::Tap: return "TAP";
    case SpindleState::Orient: return "ORIENT";
    }
    return "STOP";
}

} // namespace m350::machine
