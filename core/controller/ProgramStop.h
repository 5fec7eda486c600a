#pragma once

#include "core/common/Message.h"
#include "core/controller/TraceWriter.h"

#include <string>

namespace m350::controller {

// Why the run holds when the program itself stopped it (M00, M01 with the optional stop on, the
// M350's G04 P-1, a single block stop): "M00 program stop (main.nc:12)" for the panel and the
// report, and the same by message id for what Controller::run() says when it presses START.
class ProgramStop {
public:
    // What stopped the program (ModalInterpreter::OperatorStop::what), in both languages.
    static std::string bilingualWhat(const std::string& what);

    // The program's `what` stopped it at `where`.
    void stoppedBy(const std::string& what, const TraceSource& where);
    // Single block held the run after the block at `where`.
    void singleBlock(const TraceSource& where);
    void clear() { text_.clear(); }

    // Empty when the run is not held by the program (暂停, or running).
    const std::string& text() const { return text_; }
    // "notice_start_after_stop": START after this stop.
    const Message& startWords() const { return startWords_; }

private:
    std::string text_;
    Message startWords_; // set with text_
};

} // namespace m350::controller
