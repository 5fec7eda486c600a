// formatImportReport: the import's report in words, for the terminal, the panel and the machine
// folder's import-report.txt.
#include "core/backup/BackupImport.h"

#include <algorithm>
#include <map>

namespace m350::backup {

namespace {

constexpr std::size_t kErrorsPerFile = 5; // a factory library may have many of one kind
constexpr std::size_t kOutOfRangeShown = 10; // the JSON result lists them all

// The report in one language: every word by message id; names, keys and values as they are.
class ReportWriter {
public:
    explicit ReportWriter(MessageLanguage language) : language_(language) {}

    std::string say(const char* id, std::vector<std::string> arguments = {}) const {
        return message(id, std::move(arguments)).in(language_);
    }
    std::string say(const Message& words) const { return words.in(language_); }
    std::string colon() const { return language_ == MessageLanguage::Chinese ? "：" : ": "; }
    std::string words(const std::string& argument) const { return argumentIn(argument, language_); }
    std::string joined(const std::vector<std::string>& names) const {
        std::string text;
        for (const std::string& name : names) {
            text += (text.empty() ? "" : language_ == MessageLanguage::Chinese ? "、" : ", ") + name;
        }
        return text;
    }

    void line(const std::string& text) { out_ += "  " + text + "\n"; }
    void title(const std::string& text) { out_ += text + "\n"; }
    void section(const std::string& title, const std::vector<std::string>& lines) {
        if (lines.empty()) {
            return;
        }
        out_ += "\n" + title + "\n";
        for (const std::string& each : lines) {
            line(each);
        }
    }
    std::vector<std::string> said(const std::vector<Message>& messages) const {
        std::vector<std::string> lines;
        for (const Message& m : messages) {
            lines.push_back(say(m));
        }
        return lines;
    }
    std::vector<std::string> syntaxLines(const std::vector<gcode::Diagnostic>& diagnostics) const {
        std::map<std::string, std::size_t> perFile;
        for (const gcode::Diagnostic& d : diagnostics) {
            ++perFile[d.file];
        }
        std::vector<std::string> lines;
        std::map<std::string, std::size_t> shown;
        for (const gcode::Diagnostic& d : diagnostics) {
            std::size_t& n = shown[d.file];
            if (++n <= kErrorsPerFile) {
                lines.push_back(gcode::formatDiagnostic(d, language_));
            } else if (n == kErrorsPerFile + 1) {
                lines.push_back(say("import_report_file_more", {d.file, std::to_string(perFile[d.file] - kErrorsPerFile)}));
            }
        }
        return lines;
    }
    const std::string& text() const { return out_; }

private:
    MessageLanguage language_;
    std::string out_;
};

} // namespace

std::string formatImportReport(const BackupImport& r, MessageLanguage language) {
    ReportWriter out(language);
    out.title(out.say("import_report_title"));
    out.line(out.say("import_report_machine",
                     {"machine.toml", r.libraries.empty() ? out.say("import_report_no_libraries") : out.joined(r.libraries)}));
    out.line(out.say(r.magazine));
    if (r.factoryCompared) {
        out.line(out.say("import_report_params_changed", {"params.toml", std::to_string(r.parameters),
                                                          std::to_string(r.changedParameters.size()), "default_setting"}));
    } else {
        out.line(out.say("import_report_params", {"params.toml", std::to_string(r.parameters)}));
    }
    if (r.offsets) {
        out.line(out.say("import_report_offsets", {"offsets.toml", "coordinate"}));
    }
    if (!r.mdiLines.empty()) {
        const auto used = std::count_if(r.mdiLines.begin(), r.mdiLines.end(),
                                        [](const std::string& line) { return !line.empty(); });
        out.line(out.say("import_report_mdi", {"mdiblock", std::to_string(used)}));
    }
    out.line(r.copied.empty() ? out.say("import_report_copied", {"0"})
                              : out.say("import_report_copied_named", {std::to_string(r.copied.size()), out.joined(r.copied)}));
    out.section(out.say("import_report_hooks"), out.said(r.hooks));
    std::vector<std::string> skipped;
    for (const SkippedFile& file : r.skipped) {
        skipped.push_back(file.name + out.colon() + out.say(file.reason));
    }
    out.section(out.say("import_report_skipped", {std::to_string(r.skipped.size())}), skipped);
    std::vector<std::string> review;
    for (const ReviewItem& item : r.review) {
        review.push_back(item.key + " = " + out.words(item.value) + out.colon() + out.say(item.why));
    }
    out.section(out.say("import_report_review", {"machine.toml"}), review);
    out.section(out.say("import_report_unsupported"), out.said(r.unsupported));
    const std::size_t shown = std::min(r.outOfRange.size(), kOutOfRangeShown);
    std::vector<std::string> outOfRange =
        out.said(std::vector<Message>(r.outOfRange.begin(), r.outOfRange.begin() + static_cast<std::ptrdiff_t>(shown)));
    if (r.outOfRange.size() > kOutOfRangeShown) {
        outOfRange.push_back(out.say("import_report_more", {std::to_string(r.outOfRange.size() - kOutOfRangeShown)}));
    }
    out.section(out.say("import_report_out_of_range"), outOfRange);
    out.section(out.say("import_report_syntax"), out.syntaxLines(r.diagnostics));
    out.section(out.say("import_report_notes"), out.said(r.notes));
    return out.text();
}

} // namespace m350::backup
