#pragma once

#include "core/common/Message.h"

#include <optional>
#include <string>

namespace m350::controller {

// FANUC's automatic operation control, #3003 and #3004: what a macro switches off of the operator's
// control of the run while it works (a probing cycle that must not stop half way).
//   #3003 bit 0: no single block stop; bit 1: no wait for the completion of M, S and T functions
//   #3004 bit 0: no feed hold; bit 1: no feed override (100 %); bit 2: no exact stop check
// Both read 0 at power-on, after a reset and at the start of a run.
class OperationControl {
  public:
    double value(int variable) const { return variable == 3 ? singleBlock_ : feedHold_; }
    // #3003 (variable 3) or #3004 (4) = value; what is wrong with the value, if anything.
    std::optional<Message> set(int variable, double value);
    void reset() { singleBlock_ = feedHold_ = 0; }

    bool singleBlockSuppressed() const { return (singleBlock_ & 1) != 0; }
    bool completionWaitSuppressed() const { return (singleBlock_ & 2) != 0; }
    bool feedHoldSuppressed() const { return (feedHold_ & 1) != 0; }
    bool overrideSuppressed() const { return (feedHold_ & 2) != 0; }
    bool exactStopSuppressed() const { return (feedHold_ & 4) != 0; }

  private:
    int singleBlock_ = 0; // #3003
    int feedHold_ = 0;    // #3004
};

} // namespace m350::controller
