#pragma once

#include "core/gcode/Diagnostic.h"
#include "core/gcode/Program.h"

#include <vector>

namespace m350::gcode {

// The machine's library files parsed on their own, once, to be joined after each new main file
// (an MDI line, a program) as if they had been parsed there: Parser::startOn and joinLibraries.
// Block, unit and file indexes count from 0 here; joining moves them past the main file's.
struct ParsedLibraries {
    Program program;
    // What the parser said of them, in the order it said it (not yet sorted: Parser::finish does
    // that for the whole program).
    std::vector<Diagnostic> diagnostics;
    // False when joining could not give what parsing the files after the main file gives: the
    // parser left findings out (DiagnosticCap) or refused a file. Then the files are parsed.
    bool joinable = true;
};

} // namespace m350::gcode
