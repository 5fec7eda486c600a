#include "core/gcode/Parser.h"
#include "core/common/EchoText.h"
#include "core/common/Numeric.h"

#include "core/gcode/BlockParser.h"
#include "core/gcode/ChunkDropper.h"
#include "core/gcode/LineSplitter.h"
#include "core/gcode/ParsedLibraries.h"
#include "core/gcode/PlainBlockParser.h"
#include "core/gcode/PlainLinePrefetch.h"
#include "core/gcode/WordFacts.h"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <map>
#include <optional>
#include <utility>

namespace m350::gcode {

void Parser::addFile(Program& program, const std::string& path, std::string_view text, FileRole role,
                     std::string encoding) {
    parseFile(program, text, addFileEntry(program, path, role, std::move(encoding)), nullptr);
}

std::uint32_t Parser::addFileEntry(Program& program, const std::string& path, FileRole role, std::string encoding) {
    auto fileIndex = static_cast<std::uint32_t>(program.files.size());
    std::string name = std::filesystem::path(path).filename().string();
    program.files.push_back({path, name.empty() ? path : name, role, std::move(encoding)});
    return fileIndex;
}

void Parser::addSource(Program& program, const SourceText& source, FileRole role) {
    const std::string encoding(encodingName(source.encoding));
    const bool keptInPart = role == FileRole::Main && source.storage && source.encoding == TextEncoding::Utf8 &&
                            program.blocks.empty() && source.text.size() > dropAbove_;
    if (!keptInPart) {
        if (source.text.size() > kMostSourceBytes) {
            diagnostics_.push_back(diagnostic(Severity::Error, DiagnosticKind::Syntax, source.path, 0, 0,
                                              message("file_too_big", {std::to_string(source.text.size() >> 20),
                                                                       std::to_string(kMostSourceBytes >> 20)})));
            diagnostics_.back().unreadable = true;
            return;
        }
        addFile(program, source.path, source.text, role, encoding);
    } else {
        const std::uint32_t fileIndex = addFileEntry(program, source.path, role, encoding);
        parseFile(program, source.text, fileIndex,
                  std::make_shared<ChunkSource>(dialect_, program.files.back().name, fileIndex, source.text,
                                                source.storage, source.mapping));
    }
    if (source.mapping && source.mapping->truncated()) {
        // the lost pages read as NUL bytes: what the parser said of them is noise (it was
        // "unexpected character '\0'"), the file is what is wrong
        const std::string& name = program.files.back().name;
        std::erase_if(diagnostics_, [&name](const Diagnostic& d) { return d.file == name; });
        diagnostics_.push_back(diagnostic(Severity::Error, DiagnosticKind::Syntax, source.path, 0, 0, message("file_cut_short")));
        diagnostics_.back().unreadable = true;
    }
}

void Parser::parseFile(Program& program, std::string_view text, std::uint32_t fileIndex,
                       std::shared_ptr<ChunkSource> chunks) {
    const FileRole role = program.files[fileIndex].role;
    BlockParser blockParser(dialect_, program, diagnostics_, program.files[fileIndex].name, fileIndex);
    std::optional<ChunkDropper> dropper;
    if (chunks) {
        program.blocks.allocateChunksApart();
        dropper.emplace(program, std::move(chunks));
    }
    const bool checksCalls = role == FileRole::Main || role == FileRole::Mdi;
    bool unitOpen = false;
    std::uint32_t lineNumber = 0;
    Unreachable unreachable;
    LineSplitter lines(text);
    std::string_view line;
    std::unique_ptr<PlainLinePrefetch> prefetch;
    if (role == FileRole::Main && !dropper && blockParser.plainPath() && text.size() >= secondThreadFrom_) {
        program.blocks.expectMany();
        program.words.expectMany();
        prefetch = PlainLinePrefetch::start(text, dialect_, fileIndex);
    }
    while (true) {
        if (prefetch && lines.position() == prefetch->begin()) {
            if (unitOpen && !blockParser.commentOpen()) {
                lineNumber = adoptPrefetched(program, *prefetch, lines, lineNumber, unreachable);
            }
            prefetch.reset();
        }
        // The block is built where it is kept; it is added only at the end of this iteration. A
        // plain line is read before its end is looked for, except when chunks may be dropped (the
        // dropper marks the arenas before each line).
        Block* slot = nullptr;
        PlainResult ahead = PlainResult::Declined;
        if (!dropper && lines.lineAhead() != nullptr) {
            slot = &program.blocks.nextSlot();
            ahead = blockParser.parseAhead(lines, lineNumber + 1, *slot, line);
        }
        if (ahead == PlainResult::Declined && !lines.next(line)) {
            break;
        }
        ++lineNumber;
        cap_.trimIfLarge(diagnostics_, program);
        const std::size_t diagnosticsBefore = diagnostics_.size();
        if (dropper) {
            dropper->beforeLine(lines.lineStart(line), lines.lineStart(line) + line.size(), lineNumber,
                                blockParser.commentOpen());
        }
        Block& block = slot != nullptr ? *slot : program.blocks.nextSlot();
        const bool parsed = ahead == PlainResult::Declined ? blockParser.parse(line, lineNumber, block, lines.lineEnd())
                                                           : ahead == PlainResult::Parsed;
        if (!parsed) {
            if (diagnostics_.size() > diagnosticsBefore && unreachable.afterLine != 0 &&
                !blockParser.lastLineLabelled()) {
                demoteUnreachable(diagnosticsBefore, unreachable);
            }
            if (dropper) {
                dropper->afterLine(nullptr, diagnostics_.size() > diagnosticsBefore);
            }
            continue;
        }
        const WordFacts facts = wordFacts(block);
        unreachable.update(block, lineNumber, facts.ends);
        if (block.programNumber >= 0 || !unitOpen) {
            if (unitOpen) {
                closeUnit(program, static_cast<std::uint32_t>(program.units.size() - 1));
            }
            ProgramUnit unit;
            unit.number = block.programNumber;
            unit.file = fileIndex;
            unit.begin = static_cast<std::uint32_t>(program.blocks.size());
            program.units.push_back(std::move(unit));
            unitOpen = true;
        }
        const auto index = static_cast<std::uint32_t>(program.blocks.size());
        if (block.suspect) {
            program.suspects[index] = blockParser.lastLint();
        }
        if (block.label >= 0) {
            labelBlocks_.emplace_back(block.label, index);
        }
        if (block.control != Control::None) {
            flowBlocks_.push_back(index);
        }
        if (checksCalls && facts.call) {
            callBlocks_.push_back(index);
        }
        program.blocks.addNextSlot();
        if (dropper) {
            dropper->afterLine(&block, diagnostics_.size() > diagnosticsBefore);
        }
    }
    if (dropper) {
        dropper->finish(text.size());
    }
    if (unitOpen) {
        closeUnit(program, static_cast<std::uint32_t>(program.units.size() - 1));
    }
    if (blockParser.commentOpen()) {
        SourceLocation at = blockParser.commentStart();
        diagnostics_.push_back(diagnostic(Severity::Error, DiagnosticKind::Syntax, program.files[fileIndex].name, at.line,
                                          at.column, message("parse_block_comment_open")));
    }
}

// The blocks a PlainLinePrefetch read, appended as the loop of parseFile would have (plain blocks
// that neither call nor end a program: only their labels matter to the passes). Returns the
// number of the last line passed.
std::uint32_t Parser::adoptPrefetched(Program& program, PlainLinePrefetch& prefetch, LineSplitter& lines,
                                      std::uint32_t lineNumber, Unreachable& unreachable) {
    PlainLinePrefetch::Result read = prefetch.take();
    if (read.lines == 0 || read.linesBefore != lineNumber) {
        return lineNumber; // nothing read (or, never seen, counted otherwise): the parser reads on
    }
    const auto first = static_cast<std::uint32_t>(program.blocks.size());
    for (const auto& [label, index] : read.labels) {
        labelBlocks_.emplace_back(label, first + index);
    }
    if (!read.labels.empty()) {
        const Block& labelled = read.blocks[read.labels.back().second];
        unreachable.update(labelled, labelled.location.line, nullptr); // a jump may land there
    }
    program.blocks.append(std::move(read.blocks));
    prefetch.giveStorageTo(program);
    lines.seek(read.end);
    return lineNumber + read.lines;
}

void Parser::Unreachable::update(const Block& block, std::uint32_t lineNumber, const char* endingWord) {
    if (block.label >= 0 || block.programNumber >= 0 || block.control == Control::End) {
        afterLine = 0; // a jump, a call or a loop's exit may land here
    }
    if (block.blockDelete) {
        return;
    }
    const char* ends = endingWord ? endingWord : block.control == Control::Goto ? "GOTO" : nullptr;
    if (ends) {
        afterLine = lineNumber;
        what = ends;
    }
}

// FANUC runs a program whose text after M30 or an unconditional GOTO is not G-code, as long as
// nothing can reach it (a line with an N number can be jumped to): for `check` a lint finding.
void Parser::demoteUnreachable(std::size_t firstNew, const Unreachable& unreachable) {
    for (std::size_t i = firstNew; i < diagnostics_.size(); ++i) {
        Diagnostic& d = diagnostics_[i];
        if (d.kind == DiagnosticKind::Syntax) {
            d.kind = DiagnosticKind::Lint;
            d.message += " (never reached after the " + std::string(unreachable.what) + " on line " +
                         std::to_string(unreachable.afterLine) + ", so the program still runs)";
        }
    }
}

void Parser::startOn(Program& program, std::shared_ptr<const ParsedLibraries> libraries) {
    program.expressions = libraries->program.expressions;
    program.statements = libraries->program.statements;
    program.libraries = std::move(libraries);
}

namespace {

constexpr std::string_view kOTwice = "flow_o_twice";

// The O number a flow_o_twice finding names.
std::int32_t numberDefinedTwice(const Diagnostic& d) {
    std::int32_t number = -1;
    const std::string& text = d.messageArguments.front();
    std::from_chars(text.data(), text.data() + text.size(), number);
    return number;
}

} // namespace

bool Parser::joinLibraries(Program& program) {
    const ParsedLibraries* libraries = program.libraries.get();
    // Below this many findings no line of the libraries would have trimmed the list (trimIfLarge).
    constexpr std::size_t kUntrimmed = 2 * (DiagnosticCap::kKeepFirst + DiagnosticCap::kKeepLast);
    if (libraries == nullptr || !libraries->joinable ||
        diagnostics_.size() + libraries->diagnostics.size() > kUntrimmed) {
        return false;
    }
    const Program& part = libraries->program;
    const auto firstFile = static_cast<std::uint32_t>(program.files.size());
    const auto firstBlock = static_cast<std::uint32_t>(program.blocks.size());
    const auto firstUnit = static_cast<std::uint32_t>(program.units.size());
    // closeUnit says an O number defined twice in a library only when no file before defines it
    // (findUnit then finds the main file's): the libraries alone could not know.
    for (const Diagnostic& d : libraries->diagnostics) {
        if (d.messageId != kOTwice || !program.hasUnit(numberDefinedTwice(d))) {
            diagnostics_.push_back(d);
        }
    }
    program.files.insert(program.files.end(), part.files.begin(), part.files.end());
    for (const Block& partBlock : part.blocks) {
        Block block = partBlock;
        block.location.file += firstFile;
        if (block.partner >= 0) {
            block.partner += static_cast<std::int32_t>(firstBlock);
        }
        program.blocks.push_back(block);
    }
    for (const ProgramUnit& partUnit : part.units) {
        ProgramUnit unit;
        unit.number = partUnit.number;
        unit.file = partUnit.file + firstFile;
        unit.begin = partUnit.begin + firstBlock;
        unit.end = partUnit.end + firstBlock;
        unit.labels = partUnit.labels.shifted(firstBlock);
        program.units.push_back(std::move(unit));
    }
    for (const auto& [block, finding] : part.suspects) {
        program.suspects.emplace(block + firstBlock, finding);
    }
    program.indexUnitsOf(part, firstUnit);
    return true;
}

void Parser::closeUnit(Program& program, std::uint32_t unitIndex) {
    ProgramUnit& unit = program.units[unitIndex];
    unit.end = static_cast<std::uint32_t>(program.blocks.size());
    if (unit.number >= 0) {
        if (auto existing = program.findUnit(unit.number);
            existing && program.units[*existing].file == unit.file) {
            report(program, program.blocks[unit.begin], 1, DiagnosticKind::Flow,
                   message(kOTwice, {std::to_string(unit.number),
                                            std::to_string(program.blocks[program.units[*existing].begin].location.line)}));
        }
    }
    unit.labels.build(std::exchange(labelBlocks_, {}));
    program.indexUnit(unitIndex);
    pairLoops(program);
    checkGotos(program, unit);
    flowBlocks_.clear();
}

void Parser::report(const Program& program, const Block& block, std::uint32_t column, DiagnosticKind kind,
                    const Message& words) {
    diagnostics_.push_back(
        diagnostic(Severity::Error, kind, program.files[block.location.file].name, block.location.line, column, words));
}

// WHILE ... DOm and ENDm pair by nesting, as on FANUC: the innermost open DO must carry the same m.
void Parser::pairLoops(Program& program) {
    for (std::uint32_t b : flowBlocks_) {
        if (program.blocks[b].loopId == kUnknownLoop &&
            (program.blocks[b].control == Control::While || program.blocks[b].control == Control::End)) {
            return; // a loop line with a syntax error: its error already stops the program
        }
    }
    std::vector<std::uint32_t> open;
    // The open loops of each number, innermost last: a DO reused inside itself is said once, naming
    // the innermost open one (one finding per line however deep, so deep nesting stays linear).
    std::map<std::int32_t, std::vector<std::uint32_t>> openById;
    for (std::uint32_t b : flowBlocks_) {
        Block& block = program.blocks.mutableAt(b);
        if (block.control == Control::While) {
            std::vector<std::uint32_t>& sameNumber = openById[block.loopId];
            if (!sameNumber.empty()) {
                report(program, block, block.controlColumn, DiagnosticKind::Flow,
                       message("flow_do_open", {std::to_string(block.loopId),
                                                std::to_string(program.blocks[sameNumber.back()].location.line)}));
            }
            sameNumber.push_back(b);
            open.push_back(b);
        } else if (block.control == Control::End) {
            if (open.empty()) {
                report(program, block, block.controlColumn, DiagnosticKind::Flow,
                       message("flow_end_without_do", {std::to_string(block.loopId)}));
                continue;
            }
            Block& opener = program.blocks.mutableAt(open.back());
            if (opener.loopId != block.loopId) {
                report(program, block, block.controlColumn, DiagnosticKind::Flow,
                       message("flow_end_mismatch", {std::to_string(block.loopId), loopOpening(opener),
                                                     std::to_string(opener.location.line), std::to_string(opener.loopId)}));
                continue;
            }
            opener.partner = static_cast<std::int32_t>(b);
            block.partner = static_cast<std::int32_t>(open.back());
            openById[opener.loopId].pop_back();
            open.pop_back();
        }
    }
    for (std::uint32_t b : open) {
        const Block& block = program.blocks[b];
        report(program, block, block.controlColumn, DiagnosticKind::Flow,
               message("flow_do_without_end", {loopOpening(block), std::to_string(block.loopId)}));
    }
}

void Parser::checkGotos(const Program& program, const ProgramUnit& unit) {
    for (std::uint32_t b : flowBlocks_) {
        const Block& block = program.blocks[b];
        if ((block.control != Control::Goto && block.control != Control::IfGoto) || block.target == kNoExpr) {
            continue;
        }
        const ExprNode& target = program.expressions[block.target];
        if (target.kind != ExprKind::Number) {
            continue;
        }
        auto label = roundToInt(target.number);
        if (!unit.labels.contains(label)) {
            std::string where = unit.number >= 0 ? "O" + std::to_string(unit.number) : bilingual("this program", "本程序");
            report(program, block, target.column, DiagnosticKind::Flow,
                   message("flow_goto_no_label", {std::to_string(label), where}));
            continue;
        }
        if (block.control == Control::Goto && !block.blockDelete) {
            checkEndlessLoop(program, unit, b, label);
        }
    }
}

namespace {

// Whether running `block` may end or leave a loop: a control statement (IF, WHILE, another GOTO),
// an assignment (#3000 raises an alarm), an M code (M30, M99, a code a macro handles) or a T (a
// tool change macro), a call. Only blocks of plain G words, axes and feeds cannot.
bool mayLeave(const Block& block) {
    if (block.control != Control::None || !block.assignments.empty() || block.programEnd) {
        return true;
    }
    for (const Word& w : block.words) {
        if (w.letter == 'M' || w.letter == 'T' || !w.isNumber()) {
            return true;
        }
        if (w.letter == 'G' && (w.number == 65 || w.number == 66 || w.number == 66.1)) {
            return true;
        }
    }
    return false;
}

// The most blocks looked at between a GOTO and the label it jumps back to: a loop body longer than
// this is not judged (check stays linear in the program's size).
constexpr std::uint32_t kMostLoopBlocksJudged = 1000;

} // namespace

// `N1 GOTO1` passes `check` and runs until --max-sim-time: a jump back over blocks none of which
// can leave is a loop without an exit, a lint (the program is valid, but never meant).
void Parser::checkEndlessLoop(const Program& program, const ProgramUnit& unit, std::uint32_t gotoBlock,
                              std::int32_t label) {
    const std::optional<std::uint32_t> target = unit.labels.find(label, gotoBlock);
    if (!target || *target > gotoBlock || gotoBlock - *target > kMostLoopBlocksJudged) {
        return;
    }
    for (std::uint32_t b = *target; b < gotoBlock; ++b) {
        if (mayLeave(program.blocks[b])) {
            return;
        }
    }
    const Block& jump = program.blocks[gotoBlock];
    const Block& labelled = program.blocks[*target];
    report(program, jump, jump.controlColumn, DiagnosticKind::Lint,
           message("lint_endless_goto", {std::to_string(label), std::to_string(labelled.location.line)}));
}

void Parser::finish(const Program& program) {
    checkCalls(program);
    cap_.finish(diagnostics_, program); // in reading order, bounded
}

void Parser::checkCalls(const Program& program) {
    for (std::uint32_t b : callBlocks_) {
        const Block& block = program.blocks[b];
        for (const Word& w : block.words) {
            if (w.letter == 'P' && w.isNumber() && !program.findUnit(roundToInt(w.number)) &&
                roundToInt(w.number) != dialect_.homingProgram) {
                report(program, block, w.column, DiagnosticKind::Flow,
                       message("flow_no_program", {std::to_string(roundToInt(w.number))}));
            }
        }
    }
}

} // namespace m350::gcode
