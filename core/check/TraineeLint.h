#pragma once

#include "core/gcode/Diagnostic.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/Program.h"
#include "core/macro/VariableLayout.h"
#include "core/macro/VariableMap.h"

#include <cstdint>
#include <vector>

namespace m350::check {

// `m350-sim check --lint` and the editor: what trainees get wrong in a macro that runs but does not
// do what was meant (issue 28). Warnings, each at its line and column:
// - a WHILE waiting on an input with no timeout and no way out (it hangs when the sensor fails);
// - a local variable read before the main program sets it (it is vacant);
// - an output switched on and still on when some path reaches M30, or M99 in a program that
//   switches it off elsewhere;
// - M30 right after M6 (M350).
// The parser says the others where it reads the line: a GOTO to a label the program does not have,
// `X[#1330+#1300-1]`, a '(' nested in a comment.
class TraineeLint {
public:
    TraineeLint(const gcode::Program& program, const gcode::Dialect& dialect, const macro::VariableLayout& layout = {})
        : program_(program), dialect_(dialect), variables_(dialect, layout) {}

    // The findings about the units of one file (an index of Program::files), in line order.
    std::vector<gcode::Diagnostic> findings(std::uint32_t file) const;

private:
    const gcode::Program& program_;
    const gcode::Dialect& dialect_;
    macro::VariableMap variables_;
};

} // namespace m350::check
