#include "core/gcode/Expression.h"

namespace m350::gcode {

bool isComparison(BinaryOp op) {
    return op >= BinaryOp::Eq;
}

} // namespace m350::gcode
