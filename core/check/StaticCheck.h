#pragma once

#include "core/gcode/Diagnostic.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/Program.h"
#include "core/interp/ModalInterpreter.h"
#include "core/macro/CallCodes.h"
#include "core/macro/VariableLayout.h"

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
    // What the machine's control has beyond its dialect (config::MachineConfig): its common
    // variables and G54.1 systems, and whether it rotates (G68).
    struct Options {
        macro::VariableLayout variables;
        interp::ModalInterpreter::CoordinateFeatures coordinates;
    };
    // With the dialect's own variables, and FANUC's G54.1 P1-P48 and G68.
    StaticCheck(const gcode::Program& program, const gcode::Dialect& dialect, const macro::CallCodes& callCodes)
        : StaticCheck(program, dialect, callCodes, dialectOptions(dialect)) {}
    StaticCheck(const gcode::Program& program, const gcode::Dialect& dialect, const macro::CallCodes& callCodes,
                Options options)
        : program_(program), dialect_(dialect), callCodes_(callCodes), options_(std::move(options)) {}

    std::vector<gcode::Diagnostic> findings() const;

private:
    static Options dialectOptions(const gcode::Dialect& dialect);

    const gcode::Program& program_;
    const gcode::Dialect& dialect_;
    const macro::CallCodes& callCodes_;
    Options options_;
};

} // namespace m350::check
