#pragma once

#include "core/gcode/Diagnostic.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/Program.h"
#include "core/macro/CallCodes.h"

#include <vector>

namespace m350::check {

// `m350-sim check`: what a loaded program (its main or MDI file) would alarm on that is knowable
// without running it: a word twice in a block, an unknown G code, a variable that does not exist
// or is read-only, 1/0 in constants, an O program calling itself unconditionally. Each finding is
// what the run would say, at its place. `callCodes` are the machine's G/M codes (and FANUC
// addresses) that call a program (config::MachineConfig::callCodes): their blocks' words are the
// call's arguments.
class StaticCheck {
public:
    StaticCheck(const gcode::Program& program, const gcode::Dialect& dialect, const macro::CallCodes& callCodes)
        : program_(program), dialect_(dialect), callCodes_(callCodes) {}

    std::vector<gcode::Diagnostic> findings() const;

private:
    const gcode::Program& program_;
    const gcode::Dialect& dialect_;
    const macro::CallCodes& callCodes_;
};

} // namespace m350::check
