#pragma once

#include "core/gcode/Diagnostic.h"
#include "core/gcode/Program.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace m350::gcode {

// Sorts diagnostics in reading order: by file as parsed, then line and column (stable).
void sortInReadingOrder(std::vector<Diagnostic>& diagnostics, const Program& program);

// Keeps a parse's diagnostics bounded: a file of a million bad lines keeps its first kKeepFirst and
// last kKeepLast findings in reading order, and one finding in their place says how many were left
// out, where the first of them was, and carries the worst kind among them (so a left-out syntax
// error still stops the program).
class DiagnosticCap {
public:
    static constexpr std::size_t kKeepFirst = 500;
    static constexpr std::size_t kKeepLast = 500;

    // Called as findings accumulate: past twice the bound they are sorted and the middle dropped.
    void trimIfLarge(std::vector<Diagnostic>& diagnostics, const Program& program) {
        if (diagnostics.size() > 2 * (kKeepFirst + kKeepLast)) [[unlikely]] { // asked once a line
            sortAndTrim(diagnostics, program);
        }
    }
    // Sorts, trims and puts the note about the left-out ones between the first and the last.
    // Order::AsFiled leaves a list that was never too long in the order its findings came.
    enum class Order { Reading, AsFiled };
    void finish(std::vector<Diagnostic>& diagnostics, const Program& program, Order order = Order::Reading);

    bool leftAnyOut() const { return omitted_ > 0; }

private:
    void sortAndTrim(std::vector<Diagnostic>& diagnostics, const Program& program);
    void trim(std::vector<Diagnostic>& diagnostics, const Program& program);
    std::uint64_t omitted_ = 0;
    std::optional<Diagnostic> firstOmitted_; // in reading order, with the worst kind among them
};

} // namespace m350::gcode
