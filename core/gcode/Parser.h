#pragma once

#include "core/gcode/Dialect.h"
#include "core/gcode/Diagnostic.h"
#include "core/gcode/DiagnosticCap.h"
#include "core/gcode/Program.h"
#include "core/gcode/SourceText.h"

#include <memory>

#include <string>
#include <string_view>
#include <vector>

namespace m350::gcode {

class ChunkSource;
struct ParsedLibraries;
class LineSplitter;
class PlainLinePrefetch;

// A main program from this size on is read on two threads: below, a second thread would not pay
// for its start.
inline constexpr std::size_t kSecondThreadFrom = std::size_t{1} << 20;

// Builds a Program from any number of files (the program to run plus the machine's macro
// libraries). Every file is parsed whole; errors are collected, never thrown, so `check` can list
// them all.
class Parser {
public:
    explicit Parser(const Dialect& dialect) : dialect_(dialect) {}

    void addFile(Program& program, const std::string& path, std::string_view utf8Text, FileRole role,
                 std::string encoding = "UTF-8");

    // A file as readSourceFile gave it. A UTF-8 main program of more than setDropChunksAbove's
    // bytes is kept only in part: each chunk of plain lines is dropped once
    // parsed and parsed again when it runs (BlockList), so a 1 GB program fits in memory. Other
    // files above kMostSourceBytes are refused with a diagnostic.
    void addSource(Program& program, const SourceText& source, FileRole role);
    void setDropChunksAbove(std::size_t bytes) { dropAbove_ = bytes; }
    // A main program of at least this many bytes has its second half read on a second thread
    // (PlainLinePrefetch); tests lower it to take that path with small programs.
    void setSecondThreadFrom(std::size_t bytes) { secondThreadFrom_ = bytes; }

    // Checks that need every file: calls to O programs that exist nowhere. Then the diagnostics are
    // put in reading order and bounded (DiagnosticCap).
    void finish(const Program& program);

    const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
    // Whether findings were left out to keep the list bounded (DiagnosticCap).
    bool leftFindingsOut() const { return cap_.leftAnyOut(); }

    // Library files parsed before on their own, to be joined after the main file (joinLibraries)
    // instead of parsed again: called on an empty program, before the main file is added. Their
    // expressions and statements go first into the program's storage, so their blocks join
    // unchanged.
    void startOn(Program& program, std::shared_ptr<const ParsedLibraries> libraries);
    // Appends the libraries of startOn as if their files were added now: the same blocks, units,
    // lookups and findings. False, with nothing changed, when that cannot be exactly so (see
    // ParsedLibraries::joinable, or findings near the bound): then add the files.
    bool joinLibraries(Program& program);

private:
    std::uint32_t addFileEntry(Program& program, const std::string& path, FileRole role, std::string encoding);
    void parseFile(Program& program, std::string_view text, std::uint32_t fileIndex,
                   std::shared_ptr<ChunkSource> chunks);

    // Where the lines that no block reaches begin: after an M30, M2, M99 or GOTO, up to the next
    // N or O number or END.
    struct Unreachable {
        std::uint32_t afterLine = 0; // the line of that block, 0 while lines are reachable
        const char* what = "";
        // `endingWord`: the block's M30, M2 or M99, if it has one.
        void update(const Block& block, std::uint32_t lineNumber, const char* endingWord);
    };
    void demoteUnreachable(std::size_t firstNew, const Unreachable& unreachable);
    std::uint32_t adoptPrefetched(Program& program, PlainLinePrefetch& prefetch, LineSplitter& lines,
                                  std::uint32_t lineNumber, Unreachable& unreachable);
    void closeUnit(Program& program, std::uint32_t unitIndex);
    void pairLoops(Program& program);
    void checkGotos(const Program& program, const ProgramUnit& unit);
    void checkEndlessLoop(const Program& program, const ProgramUnit& unit, std::uint32_t gotoBlock, std::int32_t label);
    void checkCalls(const Program& program);
    void report(const Program& program, const Block& block, std::uint32_t column, DiagnosticKind kind,
                const Message& words);

    const Dialect& dialect_;
    std::size_t dropAbove_ = kProgramKeptWholeUpTo;
    std::size_t secondThreadFrom_ = kSecondThreadFrom;
    std::vector<Diagnostic> diagnostics_;
    DiagnosticCap cap_;
    // The passes over a unit look only at the blocks that matter to them, not at every G1 line:
    std::vector<std::uint32_t> flowBlocks_; // of the open unit: control statements
    std::vector<std::pair<std::int32_t, std::uint32_t>> labelBlocks_; // of the open unit: (N label, block)
    std::vector<std::uint32_t> callBlocks_; // of main and MDI files: M98 / G65 with a P number
};

} // namespace m350::gcode
