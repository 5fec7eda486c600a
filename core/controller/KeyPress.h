#pragma once

#include "core/common/Message.h"

namespace m350::controller {

// What a press of a K key or an external key did (OperatorPanel::pressUserKey, pressExternKey).
struct KeyPress {
    enum class Kind { Hook, Output, PanelKey, Refused } kind = Kind::Refused;
    int value = 0;   // the output or the panel key code
    Message why{}; // Refused: the reason
};

} // namespace m350::controller
