// formatImportReport: the import's report in words, for the terminal, the panel and the machine
// folder's import-report.txt.
#include "core/backup/BackupImport.h"

#include <algorithm>
#include <map>

namespace m350::backup {

namespace {

constexpr std::size_t kErrorsPerFile = 5; // a factory library may have many of one kind
constexpr std::size_t kOutOfRangeShown = 10; // the JSON result lists them all

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) {
        text += (text.empty() ? "" : ", ") + name;
    }
    return text;
}

void section(std::string& out, const std::string& title, const std::vector<std::string>& lines) {
    if (lines.empty()) {
        return;
    }
    out += "\n" + title + "\n";
    for (const std::string& line : lines) {
        out += "  " + line + "\n";
    }
}

std::vector<std::string> syntaxLines(const std::vector<gcode::Diagnostic>& diagnostics) {
    std::map<std::string, std::size_t> perFile;
    for (const gcode::Diagnostic& d : diagnostics) {
        ++perFile[d.file];
    }
    std::vector<std::string> lines;
    std::map<std::string, std::size_t> shown;
    for (const gcode::Diagnostic& d : diagnostics) {
        std::size_t& n = shown[d.file];
        if (++n <= kErrorsPerFile) {
            lines.push_back(gcode::formatDiagnostic(d));
        } else if (n == kErrorsPerFile + 1) {
            lines.push_back(d.file + ": and " + std::to_string(perFile[d.file] - kErrorsPerFile) + " more");
        }
    }
    return lines;
}

} // namespace

std::string formatImportReport(const BackupImport& r) {
    std::string out = "Machine folder from a controller backup\n";
    out += "  machine.toml: dialect m350, libraries " + (r.libraries.empty() ? "none" : joined(r.libraries)) + "\n";
    out += "  " + r.magazine + "\n";
    out += "  params.toml: " + std::to_string(r.parameters) + " parameters";
    if (r.factoryCompared) {
        out += ", " + std::to_string(r.changedParameters.size()) + " differ from the factory values (default_setting)";
    }
    out += "\n";
    if (r.offsets) {
        out += "  offsets.toml: G92, G54-G59, G52 and the common offset (coordinate)\n";
    }
    if (!r.mdiLines.empty()) {
        const auto used = std::count_if(r.mdiLines.begin(), r.mdiLines.end(),
                                        [](const std::string& line) { return !line.empty(); });
        out += "  mdiblock: the six MDI lines, " + std::to_string(used) + " in use\n";
    }
    out += "  copied as they were: " + std::to_string(r.copied.size()) + " .nc files" +
           (r.copied.empty() ? "" : " (" + joined(r.copied) + ")") + "\n";
    section(out, "Hook files (the panel and the controller run them as the M350 does):", r.hooks);
    std::vector<std::string> skipped;
    for (const SkippedFile& file : r.skipped) {
        skipped.push_back(file.name + ": " + file.reason);
    }
    section(out, "Not copied (" + std::to_string(r.skipped.size()) + " files the simulator does not use):", skipped);
    std::vector<std::string> review;
    for (const ReviewItem& item : r.review) {
        review.push_back(item.key + " = " + item.value + ": " + item.why);
    }
    section(out, "To review in machine.toml (no file of the backup gives these; stated values):", review);
    section(out, "The simulator cannot model:", r.unsupported);
    std::vector<std::string> outOfRange(r.outOfRange.begin(),
                                        r.outOfRange.begin() + static_cast<std::ptrdiff_t>(
                                                                   std::min(r.outOfRange.size(), kOutOfRangeShown)));
    if (r.outOfRange.size() > kOutOfRangeShown) {
        outOfRange.push_back("and " + std::to_string(r.outOfRange.size() - kOutOfRangeShown) + " more");
    }
    section(out, "Parameter values the panel would refuse (kept as the controller had them):", outOfRange);
    section(out, "Syntax the simulator does not accept yet (a library's error stops every program):",
            syntaxLines(r.diagnostics));
    section(out, "Notes:", r.notes);
    return out;
}

} // namespace m350::backup
