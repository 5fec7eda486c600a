#include "core/gcode/DiagnosticCap.h"

#include <algorithm>
#include <tuple>

namespace m350::gcode {

namespace {

// Errors that stop the program outrank flow findings, which outrank lint, which outrank warnings.
int weight(const Diagnostic& d) {
    if (d.severity == Severity::Warning) {
        return 0;
    }
    return d.kind == DiagnosticKind::Syntax ? 3 : d.kind == DiagnosticKind::Flow ? 2 : 1;
}

// By file as parsed, then line and column.
struct ReadingOrder {
    const Program& program;
    std::size_t fileOrder(const std::string& name) const {
        for (std::size_t i = 0; i < program.files.size(); ++i) {
            if (program.files[i].name == name) {
                return i;
            }
        }
        return program.files.size();
    }
    bool operator()(const Diagnostic& a, const Diagnostic& b) const {
        return std::make_tuple(fileOrder(a.file), a.line, a.column) <
               std::make_tuple(fileOrder(b.file), b.line, b.column);
    }
};

} // namespace

void sortInReadingOrder(std::vector<Diagnostic>& diagnostics, const Program& program) {
    std::stable_sort(diagnostics.begin(), diagnostics.end(), ReadingOrder{program});
}

void DiagnosticCap::sortAndTrim(std::vector<Diagnostic>& diagnostics, const Program& program) {
    sortInReadingOrder(diagnostics, program);
    trim(diagnostics, program);
}

void DiagnosticCap::trim(std::vector<Diagnostic>& diagnostics, const Program& program) {
    if (diagnostics.size() <= kKeepFirst + kKeepLast) {
        return;
    }
    const auto first = diagnostics.begin() + static_cast<std::ptrdiff_t>(kKeepFirst);
    const auto last = diagnostics.end() - static_cast<std::ptrdiff_t>(kKeepLast);
    const Diagnostic& worst = *std::max_element(first, last, [](const Diagnostic& a, const Diagnostic& b) {
        return weight(a) < weight(b);
    });
    // A finding filed later (a flow check at the unit's end) may sort before what was dropped earlier.
    if (!firstOmitted_ || ReadingOrder{program}(*first, *firstOmitted_)) {
        const Diagnostic before = firstOmitted_.value_or(*first);
        firstOmitted_ = *first;
        if (weight(before) > weight(*firstOmitted_)) {
            firstOmitted_->severity = before.severity;
            firstOmitted_->kind = before.kind;
        }
    }
    if (weight(worst) > weight(*firstOmitted_)) {
        firstOmitted_->severity = worst.severity;
        firstOmitted_->kind = worst.kind;
    }
    omitted_ += static_cast<std::uint64_t>(last - first);
    diagnostics.erase(first, last);
}

void DiagnosticCap::finish(std::vector<Diagnostic>& diagnostics, const Program& program, Order order) {
    if (order == Order::Reading || omitted_ > 0 || diagnostics.size() > kKeepFirst + kKeepLast) {
        sortInReadingOrder(diagnostics, program);
    }
    trim(diagnostics, program);
    if (!firstOmitted_) {
        return;
    }
    Diagnostic note = *firstOmitted_;
    note.omitted = omitted_;
    note.unreadable = false;
    const Message words = message("findings_omitted", {std::to_string(omitted_), std::to_string(kKeepFirst),
                                                        std::to_string(kKeepLast)});
    note.message = words.english();
    note.messageId = words.id;
    note.messageArguments = words.arguments;
    diagnostics.insert(diagnostics.begin() + static_cast<std::ptrdiff_t>(kKeepFirst), std::move(note));
}

} // namespace m350::gcode
