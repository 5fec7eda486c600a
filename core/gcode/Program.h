#pragma once

#include "core/common/Message.h"
#include "core/gcode/Block.h"
#include "core/gcode/Diagnostic.h"
#include "core/gcode/BlockList.h"
#include "core/gcode/BlockStorage.h"
#include "core/gcode/LabelIndex.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace m350::gcode {

struct ParsedLibraries;

// What a file is for: the program to run, MDI lines, or one of the machine's macro libraries.
// G-code handlers (O9000+n) are looked up in GLibrary files and M-code handlers (O10000+n) in
// MLibrary files, as the M350 does with slib-g.nc and slib-m.nc.
enum class FileRole : std::uint8_t { Main, Mdi, GLibrary, MLibrary, Library };

struct SourceFile {
    std::string path;
    std::string name; // as diagnostics show it: the base name
    FileRole role = FileRole::Main;
    std::string encoding;
};

// An O program (or the unnamed main program at the top of a file): a range of blocks with its
// own index of N labels.
struct ProgramUnit {
    std::int32_t number = -1; // O number, -1 for the unnamed main program
    std::uint32_t file = 0;
    std::uint32_t begin = 0; // first block (the O line itself, when there is one)
    std::uint32_t end = 0;   // one past the last block
    LabelIndex labels;
};

// The parsed form of every file the run needs. Built once by the Parser; never re-scanned. The
// BlockStorage it extends holds what the blocks refer to.
class Program : public BlockStorage {
public:
    std::vector<SourceFile> files;
    BlockList blocks;
    std::vector<ProgramUnit> units;

    // The unit an O number names. The main and MDI files win over libraries, so a user can try a
    // modified O20000 without editing the machine's slib-g.nc.
    std::optional<std::uint32_t> findUnit(std::int32_t number) const;
    std::optional<std::uint32_t> findHandler(std::int32_t number, FileRole libraryRole) const;

    // The first unit of the main (or MDI) file.
    std::optional<std::uint32_t> mainUnit() const;

    // Block index of label N in a unit: searched forward from `from`, then from the unit's start
    // (FANUC searches both ways).
    std::optional<std::uint32_t> findLabel(std::uint32_t unit, std::int32_t label, std::uint32_t from) const;

    std::uint32_t unitOfBlock(std::uint32_t block) const;

    // Lint findings by block: valid lines that are never what the author meant. Running such a
    // line raises an alarm instead of moving the machine somewhere wrong.
    std::unordered_map<std::uint32_t, Diagnostic> suspects;
    // What blocks read on a second thread refer to (PlainLinePrefetch).
    std::vector<std::unique_ptr<BlockStorage>> adoptedStorage;
    // Why a block with `suspect` set stops the program.
    Diagnostic suspectMessage(std::uint32_t block) const;

    const std::string& fileName(const SourceLocation& location) const { return files[location.file].name; }

    // Indexes the O number of every unit; called by the parser after each file.
    void indexUnit(std::uint32_t unitIndex);
    // Indexes the units of `part` (its files joined after this program's, their units from
    // `firstUnit` on) in the order `part` indexed them.
    void indexUnitsOf(const Program& part, std::uint32_t firstUnit);
    bool hasUnit(std::int32_t number) const { return unitsByNumber_.contains(number); }

    // Libraries parsed before, whose storage the blocks joined from them refer to (Parser::startOn).
    std::shared_ptr<const ParsedLibraries> libraries;

private:
    std::unordered_map<std::int32_t, std::vector<std::uint32_t>> unitsByNumber_;
};

} // namespace m350::gcode
