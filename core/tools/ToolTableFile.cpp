#include "core/tools/ToolTableFile.h"

#include "core/tools/ToolTableText.h"

#include "core/common/EchoText.h"
#include "core/files/MachineFileRead.h"
#include "core/gcode/DiagnosticCap.h"

#include <fstream>
#include <map>
#include <sstream>

namespace m350::tools {

namespace {

bool blank(char c) { return c == ' ' || c == '\t'; }

// The issues as `check` bounds its findings: each message's echo of the line cut to kEchoLimit, and
// the first and last DiagnosticCap::kKeepFirst/kKeepLast kept with one issue between them saying
// how many were left out (a binary file named as tool.tbl made 17 MB of JSON).
void capIssues(std::vector<ToolTableIssue>& issues) {
    using gcode::Diagnostic;
    std::vector<Diagnostic> findings;
    findings.reserve(issues.size());
    for (ToolTableIssue& issue : issues) {
        const bool error = issue.severity == ToolTableIssue::Severity::Error;
        findings.push_back(gcode::diagnostic(error ? gcode::Severity::Error : gcode::Severity::Warning,
                                             gcode::DiagnosticKind::Syntax, std::move(issue.file),
                                             static_cast<std::uint32_t>(issue.line),
                                             static_cast<std::uint32_t>(issue.column), issue.words));
    }
    gcode::DiagnosticCap cap;
    cap.finish(findings, gcode::Program{}, gcode::DiagnosticCap::Order::AsFiled);
    issues.clear();
    for (Diagnostic& d : findings) {
        issues.push_back({d.severity == gcode::Severity::Error ? ToolTableIssue::Severity::Error
                                                               : ToolTableIssue::Severity::Warning,
                          std::move(d.file), static_cast<int>(d.line), static_cast<int>(d.column),
                          std::move(d.message), d.omitted, Message{std::move(d.messageId), std::move(d.messageArguments)}});
    }
}

// The words of one line, checked as they are read. Throws nothing: the first problem ends the line.
class RowReader {
public:
    RowReader(std::string_view line, const std::string& file, int lineNumber)
        : line_(line), file_(file), lineNumber_(lineNumber) {}

    // The row, or nullopt with `issues` holding why the line is skipped (and any warnings).
    std::optional<ToolEntry> read(std::vector<ToolTableIssue>& issues) {
        ToolEntry entry;
        std::map<char, std::size_t> seen; // letter -> column
        std::size_t i = 0;
        while (true) {
            while (i < line_.size() && blank(line_[i])) ++i;
            if (i >= line_.size()) {
                break;
            }
            if (line_[i] == ';') {
                readComment(i + 1, entry, issues);
                break;
            }
            const std::size_t start = i;
            const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(line_[i])));
            ++i;
            while (i < line_.size() && !blank(line_[i]) && line_[i] != ';') ++i;
            const std::string_view value = line_.substr(start + 1, i - start - 1);
            if (auto [it, fresh] = seen.emplace(letter, start + 1); !fresh) {
                return refuse(issues, start, message("tool_table_word_twice", {std::string(1, letter), std::to_string(it->second)}));
            }
            if (auto why = setWord(entry, letter, value)) {
                return refuse(issues, start, *why);
            }
        }
        if (!seen.count('T') || !seen.count('P')) {
            return refuse(issues, 0, message(seen.count('T') ? "tool_table_no_pocket" : "tool_table_no_tool"));
        }
        return entry;
    }

private:
    std::optional<ToolEntry> refuse(std::vector<ToolTableIssue>& issues, std::size_t index, const Message& why) const {
        issues.push_back({ToolTableIssue::Severity::Error, file_, lineNumber_, static_cast<int>(index) + 1,
                          why.english(), 0, why});
        return std::nullopt;
    }

    static std::optional<Message> setWord(ToolEntry& entry, char letter, std::string_view text) {
        const std::string word = std::string(1, letter) + std::string(text);
        if (letter == 'T' || letter == 'P' || letter == 'Q') {
            std::optional<int> n = parseWholeNumber(text);
            if (!n) {
                return message("tool_table_whole_number", {word, std::string(1, letter)});
            }
            if (letter == 'T') {
                if (*n < 1) {
                    return message("tool_table_tool_from_1", {word});
                }
                entry.tool = *n;
            } else if (letter == 'P') {
                if (*n < 0 || *n > ToolTable::kMaxPocket) {
                    return message("tool_table_pocket_word", {word});
                }
                entry.pocket = *n;
            } else {
                if (*n < 0 || *n > 9) {
                    return message("tool_table_orientation_range", {word});
                }
                entry.orientation = *n;
            }
            return std::nullopt;
        }
        std::optional<double>* target = nullptr;
        for (std::size_t axis = 0; axis < kOffsetLetters.size(); ++axis) {
            if (kOffsetLetters[axis] == letter) {
                target = &entry.offsets[axis];
            }
        }
        target = letter == 'D' ? &entry.diameter : letter == 'I' ? &entry.frontAngle
                                               : letter == 'J' ? &entry.backAngle
                                                               : target;
        if (!target) {
            if (!std::isalpha(static_cast<unsigned char>(letter))) {
                return message("tool_table_not_a_word", {word});
            }
            return message("tool_table_unknown_letter", {std::string(1, letter)});
        }
        std::optional<double> v = parseTableNumber(text);
        if (!v) {
            return message(text.empty() ? "tool_table_number_after_letter" : "tool_table_number", {word, std::string(1, letter)});
        }
        *target = v;
        return std::nullopt;
    }

    void readComment(std::size_t from, ToolEntry& entry, std::vector<ToolTableIssue>& issues) const {
        CommentParts parts = splitComment(line_.substr(from), static_cast<int>(from) + 1);
        entry.comment = parts.text;
        for (const CommentProblem& problem : parts.problems) {
            const Message kept = message("tool_table_kept_as_comment", {problem.message});
            issues.push_back({ToolTableIssue::Severity::Warning, file_, lineNumber_, problem.column, kept.english(), 0, kept});
        }
        if (parts.problems.empty()) {
            entry.maxRpm = parts.maxRpm;
            entry.teeth = parts.teeth;
            entry.type = parts.type;
            entry.lengthWear = parts.lengthWear;
            entry.radiusWear = parts.radiusWear;
        }
    }

    std::string_view line_;
    const std::string& file_;
    int lineNumber_;
};

bool commentOrBlank(std::string_view line) {
    std::size_t i = 0;
    while (i < line.size() && blank(line[i])) ++i;
    return i == line.size() || line[i] == ';';
}

} // namespace

std::string formatIssue(const ToolTableIssue& issue, MessageLanguage language) {
    const bool error = issue.severity == ToolTableIssue::Severity::Error;
    const std::string words = issue.words.id.empty() ? issue.message : bilingual(issue.words);
    return issue.file + ":" + std::to_string(issue.line) + ":" + std::to_string(issue.column) + ": " +
           messageText(!error ? "tool_table_warning" : issue.omitted == 0 ? "tool_table_error_skipped" : "tool_table_error",
                       {words}, language);
}

bool ParsedToolTable::skippedLines() const {
    for (const ToolTableIssue& issue : issues) {
        if (issue.severity == ToolTableIssue::Severity::Error) {
            return true;
        }
    }
    return false;
}

ParsedToolTable parseToolTable(std::string_view text, const std::string& fileName) {
    ParsedToolTable out;
    const bool crlf = text.find("\r\n") != std::string_view::npos;
    out.table.setLineEnd(crlf ? "\r\n" : "\n");
    out.table.setFinalLineEnd(text.empty() || text.back() == '\n');
    std::map<int, int> toolLine, pocketLine;
    int number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        std::string_view line = text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
        start = end == std::string_view::npos ? text.size() : end + 1;
        ++number;
        if (!line.empty() && line.back() == '\r') {
            line.remove_suffix(1);
        }
        if (commentOrBlank(line)) {
            out.table.appendText(std::string(line));
            continue;
        }
        std::optional<ToolEntry> entry = RowReader(line, fileName, number).read(out.issues);
        auto refuse = [&](const Message& why) {
            out.issues.push_back({ToolTableIssue::Severity::Error, fileName, number, 1, why.english(), 0, why});
            entry.reset();
        };
        if (entry && toolLine.count(entry->tool)) {
            refuse(message("tool_table_tool_twice", {std::to_string(entry->tool), std::to_string(toolLine[entry->tool])}));
        } else if (entry && pocketLine.count(entry->pocket)) {
            refuse(message("tool_table_pocket_twice", {std::to_string(entry->pocket), std::to_string(pocketLine[entry->pocket])}));
        } else if (entry && out.table.size() >= static_cast<std::size_t>(ToolTable::kMaxTools)) {
            refuse(message("tool_table_too_many", {std::to_string(ToolTable::kMaxTools)}));
        }
        if (!entry) {
            out.table.appendText(std::string(line));
            continue;
        }
        toolLine[entry->tool] = number;
        pocketLine[entry->pocket] = number;
        out.table.appendRow(std::move(*entry), std::string(line));
    }
    capIssues(out.issues);
    return out;
}

std::string formatToolEntry(const ToolEntry& entry) {
    std::string out = "T" + std::to_string(entry.tool) + " P" + std::to_string(entry.pocket);
    auto word = [&out](char letter, const std::optional<double>& v) {
        if (v) {
            out += ' ';
            out += letter;
            out += tableNumber(*v);
        }
    };
    for (std::size_t axis = 0; axis < kOffsetLetters.size(); ++axis) {
        word(kOffsetLetters[axis], entry.offsets[axis]);
    }
    word('D', entry.diameter);
    word('I', entry.frontAngle);
    word('J', entry.backAngle);
    if (entry.orientation) {
        out += " Q" + std::to_string(*entry.orientation);
    }
    const std::string comment = joinComment(entry);
    if (!comment.empty()) {
        out += " ;" + comment;
    }
    return out;
}

std::string formatToolTable(const ToolTable& table) {
    std::string out;
    const std::vector<ToolTable::Line>& lines = table.lines();
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const ToolTable::Line& line = lines[i];
        out += line.entry && line.text.empty() ? formatToolEntry(*line.entry) : line.text;
        if (i + 1 < lines.size() || table.finalLineEnd()) {
            out += table.lineEnd();
        }
    }
    return out;
}

std::variant<ParsedToolTable, Message> readToolTableFile(const std::filesystem::path& path) {
    std::string bytes;
    if (auto why = files::readMachineFile(path, bytes)) {
        return message("tool_table_unreadable", {path.string(), bilingual(*why)});
    }
    return parseToolTable(bytes, path.string());
}

} // namespace m350::tools
