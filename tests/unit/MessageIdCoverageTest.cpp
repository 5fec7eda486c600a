// Every alarm and finding is said by a message id (translations/messages.tsv), so the panel and
// `m350-sim --lang` can say it in their language: a corpus of broken programs, one per kind of
// mistake, run and checked as m350-sim does, must produce no alarm or finding without an id; and
// the core's sources may raise no more alarms or findings from bare English text than the ones
// still listed here (the list only shrinks: a new one is raised with message("id", ...)).
#include "RunProgram.h"

#include "core/check/StaticCheck.h"
#include "core/common/EchoText.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

namespace m350 {
namespace {

struct BrokenProgram {
    const char* what;
    const char* text;
    bool fanuc = false;
};

const BrokenProgram kCorpus[] = {
    {"division by zero", "#1=0\n#2=5/#1\nM30\n"},
    {"MOD by zero", "#1=0\n#2=5 MOD #1\nM30\n", true},
    {"SQRT of a negative number", "#1=SQRT[-1]\nM30\n"},
    {"overflow", "#1=99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999*99999999\nM30\n", true},
    {"exponent notation", "#1=1E3\nM30\n"},
    {"undefined variable", "#1=#9876\nM30\n"},
    {"variable number out of range", "#1=#[-1]\nM30\n"},
    {"read-only variable", "#5021=1\nM30\n", true},
    {"GOTO with no label", "GOTO 40\nM30\n"},
    {"computed GOTO with no label", "#1=40\nGOTO #1\nM30\n"},
    {"END without DO", "END1\nM30\n"},
    {"DO without END", "WHILE [1 EQ 1] DO1\nM30\n"},
    {"unknown program", "M98 P7777\nM30\n"},
    {"call nesting", "O1\nM98 P1\nM99\n"},
    {"G01 with no feed", "G90 G01 X10 F0\nM30\n"},
    {"unknown G code", "G5.1 Q1\nM30\n"},
    {"word twice", "G90 X1 X2\nM30\n"},
    {"canned cycle without R", "G90 G81 X0 Y0 Z-5 F100\nM30\n", true},
    {"tapping with the spindle stopped", "G90 M05 G84 X0 Y0 Z-5 R2 F100\nM30\n", true},
    {"IF without GOTO or THEN", "IF [1 EQ 1] X10\nM30\n"},
    {"THEN without assignment", "IF [1 EQ 1] THEN\nM30\n"},
    {"unbalanced bracket", "#1=[1+2]]\nM30\n"},
    {"missing bracket", "#1=[1+2\nM30\n"},
    {"address without value", "G01 X\nM30\n"},
    {"program number out of range", "O123456789\nM30\n"},
    {"bad loop number", "WHILE [1 EQ 1] DO9\nEND9\nM30\n", true},
    {"endless loop", "WHILE [1 EQ 1] DO1\nG04 P1000000\nEND1\nM30\n"},
    {"unknown word", "G01 X1 @\nM30\n"},
    {"lower-case keyword", "#1=1\nif [#1 EQ 1] GOTO 5\nN5 M30\n"},
    {"table added instead of indexed", "#1=3\nG53 X[#1330+#1]\nM30\n"},
    {"comment not closed", "G01 X1 (open\nM30\n"},
    {"DPRNT on the M350", "DPRNT[X#1[53]]\nM30\n"},
    {"external output of FANUC in its dialect", "MSETDATA[200,1,0,4,16,300]\nM30\n", true},
    {"a program calling itself", "O100\nM98 P100\nM99\n"},
};

std::string list(const std::vector<gcode::Diagnostic>& diagnostics) {
    std::string out;
    for (const gcode::Diagnostic& d : diagnostics) {
        out += "  " + gcode::formatDiagnostic(d) + (d.messageId.empty() ? "   <- no message id" : "") + "\n";
    }
    return out;
}

TEST(MessageIdCoverage, EveryAlarmAndFindingOfTheBrokenProgramsHasAnId) {
    for (const BrokenProgram& broken : kCorpus) {
        SCOPED_TRACE(broken.what);
        test::ProgramRun run = test::loadProgram(broken.fanuc ? test::fanucMachine() : test::m350Machine(), broken.text);
        if (run.loaded) {
            run.report = run.controller->run();
        }
        std::vector<gcode::Diagnostic> found = run.controller->diagnostics();
        if (!gcode::hasBlockingError(found)) { // what `m350-sim check` adds
            const config::MachineConfig& machine = run.controller->config();
            std::vector<gcode::Diagnostic> findings =
                check::StaticCheck(run.controller->program(), *machine.dialect, machine.callCodes).findings();
            found.insert(found.end(), findings.begin(), findings.end());
        }
        EXPECT_TRUE(!found.empty() || run.report.alarm) << "no alarm and no finding: the corpus lost a mistake";
        for (const gcode::Diagnostic& d : found) {
            EXPECT_FALSE(d.messageId.empty()) << list(found);
            EXPECT_EQ(d.message, clipEcho(messageText(d.messageId, d.messageArguments, MessageLanguage::English)));
        }
        if (run.report.alarm) {
            const Alarm& a = *run.report.alarm;
            EXPECT_FALSE(a.messageId.empty()) << run.alarmText();
            EXPECT_EQ(a.message, messageText(a.messageId, a.messageArguments, MessageLanguage::English));
        }
    }
}

// The golden corpus (tests/golden): every alarm the core raised and every finding in the outputs
// m350-sim must reproduce carries its message id.
TEST(MessageIdCoverage, EveryAlarmAndFindingOfTheGoldenCorpusHasAnId) {
    const std::filesystem::path golden = std::filesystem::path(M350_CORE_SOURCE_DIR) / ".." / "tests" / "golden";
    int alarms = 0;
    int findings = 0;
    for (const auto& entry : std::filesystem::directory_iterator(golden)) {
        const std::filesystem::path expected = entry.path() / "expected.json";
        if (!std::filesystem::exists(expected)) {
            continue;
        }
        SCOPED_TRACE(entry.path().filename().string());
        const nlohmann::json output = nlohmann::json::parse(std::ifstream(expected));
        if (output.contains("alarm") && output["alarm"].is_object()) {
            const std::string code = output["alarm"].value("code", "");
            if (code != "file_error" && code != "config_error") {
                ++alarms;
                EXPECT_TRUE(output["alarm"].contains("message_id")) << output["alarm"];
            }
        }
        for (const nlohmann::json& finding : output.value("diagnostics", nlohmann::json::array())) {
            ++findings;
            EXPECT_TRUE(finding.contains("message_id")) << finding;
        }
    }
    EXPECT_GT(alarms, 10);
    EXPECT_GT(findings, 5);
}

// Where the core raises an alarm or a finding from bare text, line by line: a MacroError or Alarm
// built from a string instead of Alarm::of / MacroError::of(code, message(...)), a file error or a
// word refused (ModalInterpreter::invalid) from a string, a parser or checker finding from a string.
// A line that calls message( is said by id.
int bareRaises(const std::string& file, const std::string& source) {
    static const std::regex alarm(R"re(MacroError\{|\{AlarmCode::|raise\(AlarmCode::|SourceReadError\{|\binvalid\(.*("|\+))re");
    static const std::regex finding(R"re(\b(fail|failAt|report|lint|note)\(.*("|\+))re");
    // A machine folder's load error or warning (core/config) from text: fail(file, "..." or a string
    // built in the call, a warning pushed as text, a magazine refusal from text.
    static const std::regex configBare(
        R"re(\bfail\(\w+, *("|std::string|\w+ \+)|\bfail\(\w+, *$|warnings\.push_back|\bwarn\(" *|Invalid\{ *("|std::string))re");
    // a message whose argument is a deeper layer's reason (the change journal's, toollife.txt's,
    // spindle-load.toml's, the file reader's, the variable layout's) passed on as its English
    // instead of nested with bilingual(Message)
    static const std::regex passedOn(
        R"re(config_(journal_broken|tool_life_unreadable|spindle_load_wrong|tool_table_unreadable|common_refused))re");
    // The files whose reasons reach the operator inside another message: a reason returned, thrown
    // or given as English words ("it is a FIFO...", "cannot " + ...) instead of message("id", ...).
    static const std::set<std::string> reasonFiles{
        "files/MachineFileRead.cpp", "files/Toml.cpp",         "files/AtomicFile.cpp",        "files/ChangeJournal.cpp",
        "tools/ToolLifeFile.cpp",    "tools/SpindleLoadLimits.cpp", "macro/VariableLayout.cpp", "config/MachineFolder.cpp"};
    static const std::regex reasonGiven(R"re(\b(return|throw)\b|\b(at|failure)\()re");
    static const std::regex literal(R"re("(?:[^"\\]|\\.)*")re");
    static const std::regex englishWord("[A-Za-z]{3,}");
    const auto hasEnglishLiteral = [](const std::string& line) {
        for (auto it = std::sregex_iterator(line.begin(), line.end(), literal); it != std::sregex_iterator(); ++it) {
            const std::string text = it->str();
            if (text.find(' ') != std::string::npos && std::regex_search(text, englishWord)) {
                return true;
            }
        }
        return false;
    };
    const bool parser = file.rfind("gcode/", 0) == 0 || file.rfind("check/", 0) == 0;
    const bool config = file.rfind("config/", 0) == 0;
    const bool reasons = reasonFiles.count(file) > 0;
    int count = 0;
    std::istringstream lines(source);
    for (std::string line; std::getline(lines, line);) {
        const bool nested = line.find("bilingual(") != std::string::npos;
        if (config && (std::regex_search(line, configBare) || (std::regex_search(line, passedOn) && !nested))) {
            ++count;
            continue;
        }
        if (reasons && !nested && line.find("message(") == std::string::npos && std::regex_search(line, reasonGiven) &&
            hasEnglishLiteral(line)) {
            ++count;
            continue;
        }
        if (line.find("message(") != std::string::npos) {
            continue;
        }
        count += std::regex_search(line, alarm) || (parser && std::regex_search(line, finding)) ? 1 : 0;
    }
    return count;
}

// The files that still do, with how many: lower a count when a raise there gets its id (the test
// says when one is lower than listed), never raise one.
const std::map<std::string, int> kStillBare = {
#include "MessageIdCoverageList.inc"
};

TEST(MessageIdCoverage, NoNewAlarmOrFindingIsRaisedFromBareText) {
    std::map<std::string, int> found;
    const std::filesystem::path core(M350_CORE_SOURCE_DIR);
    for (const auto& entry : std::filesystem::recursive_directory_iterator(core)) {
        if (entry.path().extension() != ".cpp") {
            continue;
        }
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        const std::string file = std::filesystem::relative(entry.path(), core).generic_string();
        if (const int count = bareRaises(file, text.str()); count > 0) {
            found[file] = count;
        }
    }
    for (const auto& [file, count] : found) {
        const auto listed = kStillBare.find(file);
        const int allowed = listed == kStillBare.end() ? 0 : listed->second;
        EXPECT_LE(count, allowed) << file << " raises " << count - allowed
                                  << " more alarm(s) or finding(s) from bare text: give each a message id "
                                     "(translations/messages.tsv, core/common/Message.h)";
        EXPECT_GE(count, allowed) << file << ": " << allowed - count
                                  << " fewer bare raise(s) than tests/unit/MessageIdCoverageList.inc lists: lower it";
    }
    for (const auto& [file, count] : kStillBare) {
        EXPECT_TRUE(found.count(file) > 0) << file << " has no bare raise left: remove it from the list";
    }
}

// The import's report (import-report.txt, the panel's import summary, what `m350-sim import` prints)
// and the System Log's own errors: every word the operator reads is a message by id. A statement
// here with an English literal (a space and a word) counts, unless it calls message( or
// bilingual(, holds the Chinese beside the English (a pair), is the English half of a pair whose
// Chinese is the next statement, or writes a machine folder file's own text (machine.toml's,
// params.toml's and [[io_links]] comments: `text +=`, `Toml +=`), which stays as the file has it.
const char* const kWordFiles[] = {"backup/BackupImport.cpp",     "backup/BackupImportReport.cpp", "backup/BackupWiring.cpp",
                                  "backup/BackupMachineToml.cpp", "backup/BackupPrograms.cpp",     "backup/ControllerBackup.cpp",
                                  "files/SystemLog.cpp"};

bool hasChineseText(const std::string& text) {
    return std::any_of(text.begin(), text.end(), [](char c) {
        const auto lead = static_cast<unsigned char>(c);
        return lead >= 0xE4 && lead <= 0xE9;
    });
}

// A brace that opens or closes a block (the last thing on its line, or the first), not an
// initializer list inside a statement ({"coordinate"}).
bool blockBrace(const std::string& source, std::size_t at) {
    const std::size_t lineEnd = std::min(source.find('\n', at), source.size());
    const std::size_t lineStart = source.rfind('\n', at) == std::string::npos ? 0 : source.rfind('\n', at) + 1;
    const std::string after = source.substr(at + 1, lineEnd - at - 1);
    const std::string before = source.substr(lineStart, at - lineStart);
    const auto blank = [](const std::string& text) {
        return text.find_first_not_of(" \t\r") == std::string::npos || text.find_first_not_of(" \t\r") == text.find("//");
    };
    return blank(after) || blank(before);
}

// The source's statements (split at ; and at block braces outside literals), comments dropped.
std::vector<std::string> statements(const std::string& source) {
    std::vector<std::string> out;
    std::string current;
    bool inLiteral = false;
    for (std::size_t i = 0; i < source.size(); ++i) {
        const char c = source[i];
        if (!inLiteral && c == '/' && i + 1 < source.size() && source[i + 1] == '/') {
            i = std::min(source.find('\n', i), source.size() - 1);
            continue;
        }
        if (inLiteral && c == '\\' && i + 1 < source.size()) {
            current += source.substr(i, 2);
            ++i;
            continue;
        }
        if (c == '"' && (i == 0 || source[i - 1] != '\'')) {
            inLiteral = !inLiteral;
        }
        if (!inLiteral && (c == ';' || ((c == '{' || c == '}') && blockBrace(source, i)))) {
            out.push_back(current);
            current.clear();
            continue;
        }
        current += c;
    }
    out.push_back(current);
    return out;
}

std::vector<std::string> bareWords(const std::string& source) {
    static const std::regex literal(R"re("(?:[^"\\]|\\.)*")re");
    static const std::regex word("[A-Za-z]{3,}");
    static const std::regex fileText(R"re(\b(\w*[tT]ext|\w*Toml|body|comment) *\+?= )re");
    const std::vector<std::string> all = statements(source);
    std::vector<std::string> found;
    for (std::size_t i = 0; i < all.size(); ++i) {
        const std::string& s = all[i];
        bool english = false;
        for (auto it = std::sregex_iterator(s.begin(), s.end(), literal); it != std::sregex_iterator(); ++it) {
            const std::string text = it->str();
            english = english || (text.find(' ') != std::string::npos && std::regex_search(text, word));
        }
        if (!english || s.find("message(") != std::string::npos || s.find("bilingual(") != std::string::npos ||
            hasChineseText(s) || std::regex_search(s, fileText)) {
            continue;
        }
        const bool pairedWithNext = i + 1 < all.size() && hasChineseText(all[i + 1]);
        if (!pairedWithNext) {
            found.push_back(s);
        }
    }
    return found;
}

TEST(MessageIdCoverage, TheScanOfTheImportReportFindsBareEnglish) {
    EXPECT_EQ(bareWords("        result.notes.push_back(\"no coordinate file: every work offset is 0\");\n").size(), 1u);
    EXPECT_EQ(bareWords("    *error = path_ + \": cannot append to the system log: \" + std::strerror(errno);\n").size(), 1u);
    EXPECT_EQ(bareWords("    result.notes.push_back(message(\"import_note_no_coordinate\", {\"coordinate\"}));\n").size(), 0u);
    EXPECT_EQ(bareWords("    std::string english = \"parameter \" + n;\n    std::string chinese = \"参数\" + n;\n").size(), 0u);
    EXPECT_EQ(bareWords("    out.text += \"\\n# The fixed setter's top\\n\";  // the file's own words\n").size(), 0u);
    EXPECT_EQ(bareWords("    // a comment \"with words\" is no text\n").size(), 0u);
}

TEST(MessageIdCoverage, TheImportReportAndTheSystemLogSayNoBareEnglish) {
    const std::filesystem::path core(M350_CORE_SOURCE_DIR);
    for (const char* file : kWordFiles) {
        std::ifstream in(core / file);
        ASSERT_TRUE(in) << file;
        std::stringstream text;
        text << in.rdbuf();
        std::string bare;
        for (const std::string& statement : bareWords(text.str())) {
            bare += "\n  " + statement;
        }
        EXPECT_EQ(bare, "") << file << " says English words without a message id: give each an id in "
                                      "translations/messages.tsv (core/common/Message.h)";
    }
}

} // namespace
} // namespace m350
