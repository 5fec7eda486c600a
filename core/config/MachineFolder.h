#pragma once

#include "core/files/AtomicFile.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace m350::tools {
class ToolTable;
struct LifeData;
} // namespace m350::tools

namespace m350::config {

// The files of a machine folder that the store names, besides its hook programs (config/HookFiles
// names those). Not here: the macro libraries machine.toml lists, and spindle-load.toml, which the
// loader reads by tools::kSpindleLoadFileName; isFolderFile does not know them.
enum class FolderFile : std::uint8_t {
    Machine,        // machine.toml: read only
    Offsets,        // offsets.toml: read only
    Variables,      // variables.toml: read only
    Modbus,         // modbus.toml: read only
    Params,         // params.toml: the parameters the panel sets, the M350's tool Z beside tool.tbl
    ToolTable,      // tool.tbl
    ToolLife,       // toollife.txt
    Passwords,      // passwords.toml: the panel's levels
    MdiBlock,       // mdiblock: the MDI page's lines
    MdiProgram,     // mdi.nc: the MDI line that runs (also the Mdi hook's file)
    BreakPoint,     // breakpoint: where a paused or reset run stopped
    ExternalOutput, // dprnt.txt: what the panel's programs sent to POPEN/DPRNT
    ParamsBackup,   // params-backup.toml: Param Backup
    WorkRecord,     // PROCES_MSG.txt: the work record exported ("To U Disk")
    SystemLog,      // system-log.tsv: the 系统日志 (appended by files::SystemLog)
};

// How the store writes a file.
enum class FolderWrite : std::uint8_t {
    Never,           // an input: the store never writes it
    Atomically,      // files::writeFileAtomically
    KeepingLastGood, // files::saveKeepingLastGood: the file and its NAME.last-good copy
    AsOutput,        // files::writeOutputFile: a result, as m350-sim writes one
    Appended,        // by its own writer (files::SystemLog), at the path the store names
};

struct FolderFileInfo {
    FolderFile file;
    std::string_view name; // in the folder
    FolderWrite how;
};

// One machine folder's files: where each is, how each is written, and whether a path is one of
// them. Every writer of a machine folder goes through here, so that the atomic write and the
// last-good copy are one rule; an output writer asks isFolderFile before writing a result.
class MachineFolder {
public:
    explicit MachineFolder(std::filesystem::path folder) : folder_(std::move(folder)) {}

    static std::span<const FolderFileInfo> files(); // in the order of FolderFile
    static std::string_view fileName(FolderFile file);

    const std::filesystem::path& path() const { return folder_; }
    std::filesystem::path pathOf(FolderFile file) const { return folder_ / fileName(file); }

    // Writes a file whole as the table says (atomically, with its last-good copy where due). A
    // file the store never writes, or a folder that is empty (a machine built in memory), is
    // refused. nullopt on success, else why (naming the file); a failed write leaves the old file.
    std::optional<Message> write(FolderFile file, std::string_view content,
                                     const files::AtomicWriteHooks& hooks = {}) const;
    // params.toml ([params] N = value) edited in place (params::setTomlNumbers); created when
    // there is none. With `addMissing` false only the values the file lists change (no file:
    // nothing is written).
    std::optional<Message> saveParameters(const std::map<int, double>& values, bool addMissing = true) const;
    // tool.tbl and, as one change (files::writeTogether: a crash leaves both old or both new), the
    // M350's Z parameters (930-945, 973-992; empty on a FANUC) that params.toml already lists, so
    // both files agree (tool.tbl is the one read), with `parameters` besides (added when missing,
    // as saveParameters does). `hooks` interrupt the change (see writeTogether).
    std::optional<Message> saveToolTable(const tools::ToolTable& table, const std::map<int, double>& zParameters,
                                             const files::AtomicWriteHooks& hooks = {},
                                             const std::map<int, double>& parameters = {}) const;
    std::optional<Message> saveToolLife(const tools::LifeData& data, const files::AtomicWriteHooks& hooks = {}) const;
    // A tool table exported to `target` (any path, atomically); refused over a file of this folder.
    std::optional<Message> exportToolTable(const std::filesystem::path& target, const tools::ToolTable& table) const;

    // A save of several files that a crash interrupted (kChangeJournal) finished or dropped, so
    // that the folder holds one whole state; loadMachineFolder and every save of several files
    // call it first (a write of one file finishes a journaled change but leaves stray pending files).
    // nullopt when the folder is whole, else why (naming the file).
    std::optional<Message> finishInterruptedChange() const;
    static constexpr std::string_view kChangeJournal = "save.journal";

    // Whether `path` (after resolving symlinks and `..`) is a file of this folder: one of the
    // table, a last-good or .pending copy of one, the change journal, or a hook program. Such a
    // file is never a run's output.
    bool isFolderFile(const std::filesystem::path& path) const;
    // "PATH is a file of the machine folder FOLDER: refused, nothing was written" when it is one.
    std::optional<Message> refuseFolderFile(const std::filesystem::path& path) const;

private:
    std::filesystem::path folder_;
};

} // namespace m350::config
