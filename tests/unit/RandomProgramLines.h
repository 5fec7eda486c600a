#pragma once

// Lines of random programs for the tests that compare two ways of reading a program (kept in
// part, read on two threads): every kind of line a program holds, each at random places.

#include <string>

namespace m350 {

// A plain G1 line told apart by its number.
inline std::string g1Line(int i) {
    return "G1 X" + std::to_string(i % 97) + "." + std::to_string(i % 10) + " Y-" + std::to_string(i % 89) +
           " F" + std::to_string(500 + i % 7);
}

// Appends the line (or lines) of kind `kind` (0-99) for line i, each ended by `end` (LF, CRLF or
// a lone CR): plain G1 lines (0-59), labelled (60-64), comments (65-69), blank (70-73), a
// `/* */` comment over three lines (74-75), block delete (76), an assignment (77-79), a WHILE
// loop while `loopsLeft` (80-82), an expression (83-85), a G1 line with a comment (86-99).
inline void appendRandomLine(std::string& text, int kind, int i, const char* end, int& loopsLeft) {
    if (kind < 60) {
        text += g1Line(i);
    } else if (kind < 65) {
        text += "N" + std::to_string(i + 1) + " " + g1Line(i);
    } else if (kind < 70) {
        text += "(a comment " + std::to_string(i) + ")";
    } else if (kind < 74) {
        text += "";
    } else if (kind < 76) {
        text += g1Line(i) + " /* runs on";
        text += end;
        text += "over " + std::to_string(i) + " lines";
        text += end;
        text += "*/ G0 Z" + std::to_string(i % 50);
    } else if (kind < 77) {
        text += "/" + g1Line(i);
    } else if (kind < 80) {
        text += "#" + std::to_string(100 + i % 50) + " = " + std::to_string(i) + " * 2";
    } else if (kind < 83 && loopsLeft > 0) {
        --loopsLeft;
        text += "#1 = 0";
        text += end;
        text += "WHILE [#1 LT 2] DO1";
        text += end;
        text += g1Line(i);
        text += end;
        text += "#1 = #1 + 1";
        text += end;
        text += "END1";
    } else if (kind < 86) {
        text += "G1 X[" + std::to_string(i % 9) + " + 1] F500"; // an expression
    } else {
        text += g1Line(i) + " (after " + std::to_string(i) + ")";
    }
    text += end;
}

} // namespace m350
