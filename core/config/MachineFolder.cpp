#include "core/config/MachineFolder.h"

#include "core/config/HookFiles.h"
#include "core/files/ChangeJournal.h"
#include "core/files/LastGoodCopy.h"
#include "core/files/MachineFileRead.h"
#include "core/files/OutputFile.h"
#include "core/files/OutputGuard.h"
#include "core/params/ParameterBackup.h"
#include "core/params/ParameterCatalogue.h"
#include "core/params/ParamsFileWriter.h"
#include "core/tools/ToolLifeFile.h"
#include "core/tools/ToolTableFile.h"

#include <array>
#include <cctype>
#include <fstream>
#include <sstream>

namespace m350::config {

namespace fs = std::filesystem;

namespace {

using F = FolderFile;
using W = FolderWrite;

// In the order of the enum: fileName() indexes it.
constexpr std::array kFiles{
    FolderFileInfo{F::Machine, "machine.toml", W::Never},
    FolderFileInfo{F::Offsets, "offsets.toml", W::Never},
    FolderFileInfo{F::Variables, "variables.toml", W::Never},
    FolderFileInfo{F::Modbus, "modbus.toml", W::Never},
    FolderFileInfo{F::Params, "params.toml", W::KeepingLastGood},
    FolderFileInfo{F::ToolTable, tools::kToolTableFileName, W::KeepingLastGood},
    FolderFileInfo{F::ToolLife, tools::kToolLifeFile, W::KeepingLastGood},
    FolderFileInfo{F::Passwords, "passwords.toml", W::Atomically},
    FolderFileInfo{F::MdiBlock, "mdiblock", W::Atomically},
    FolderFileInfo{F::MdiProgram, kMdiProgramFile, W::Atomically},
    FolderFileInfo{F::BreakPoint, "breakpoint", W::Atomically},
    FolderFileInfo{F::ExternalOutput, "dprnt.txt", W::AsOutput},
    FolderFileInfo{F::ParamsBackup, params::kParameterBackupFile, W::Atomically},
    FolderFileInfo{F::WorkRecord, "PROCES_MSG.txt", W::Atomically},
    FolderFileInfo{F::SystemLog, "system-log.tsv", W::Appended},
};

std::optional<Message> readText(const fs::path& file, std::string& text) {
    if (auto why = files::readMachineFile(file, text)) {
        return message("folder_cannot_read", {file.string(), bilingual(*why)});
    }
    return std::nullopt;
}

// The path with its symlinks followed, also a last one whose target does not exist yet, and
// `.`/`..` gone.
fs::path resolved(const fs::path& path) {
    std::error_code ec;
    fs::path p = fs::absolute(path, ec);
    for (int hops = 0; hops < 40 && fs::is_symlink(p, ec); ++hops) {
        const fs::path target = fs::read_symlink(p, ec);
        if (ec) {
            break;
        }
        p = target.is_absolute() ? target : p.parent_path() / target;
    }
    fs::path out = fs::weakly_canonical(p, ec);
    return ec ? p.lexically_normal() : out;
}

bool endsWith(std::string_view text, std::string_view end) {
    return text.size() >= end.size() && text.substr(text.size() - end.size()) == end;
}

// A hook program's name, in any case as hookPath finds it ("FNDZERO.NC").
bool isHookFile(std::string_view name) {
    if (name.size() <= 3) {
        return false;
    }
    std::string extension(name.substr(name.size() - 3));
    for (char& c : extension) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return extension == ".nc" && findHook(name) != nullptr;
}

// params.toml's text with `values` set, each at its parameter's resolution.
std::string withParameters(const std::string& text, std::map<int, double> values, bool addMissing) {
    if (const auto* catalogue = std::get_if<params::ParameterCatalogue>(&params::ParameterCatalogue::bundled())) {
        for (auto& [number, value] : values) {
            value = catalogue->atResolution(number, value);
        }
    }
    return params::setTomlNumbers(text, "params", values, addMissing);
}

} // namespace

std::span<const FolderFileInfo> MachineFolder::files() { return kFiles; }

std::string_view MachineFolder::fileName(FolderFile file) { return kFiles[static_cast<std::size_t>(file)].name; }

std::optional<Message> MachineFolder::write(FolderFile file, std::string_view content,
                                                const files::AtomicWriteHooks& hooks) const {
    const FolderFileInfo& info = kFiles[static_cast<std::size_t>(file)];
    if (folder_.empty()) {
        return message("folder_none", {std::string(info.name)});
    }
    // A change a crash interrupted is finished first; pending files left without a journal are
    // harmless to this write (loading the folder and the next change of several files remove
    // them), so one stat does here, as the MDI page writes mdi.nc and mdiblock at every line.
    if (auto error = files::finishInterruptedChange(folder_ / kChangeJournal, {})) {
        return error;
    }
    const fs::path target = pathOf(file);
    switch (info.how) {
    case W::Atomically:
        return files::writeFileAtomically(target, content, hooks);
    case W::KeepingLastGood:
        return files::saveKeepingLastGood(target, content, hooks);
    case W::AsOutput:
        return files::writeOutputFile(target, content);
    case W::Never:
    case W::Appended:
        break;
    }
    return message("folder_not_written", {target.string()});
}

std::optional<Message> MachineFolder::saveParameters(const std::map<int, double>& values, bool addMissing) const {
    const fs::path file = pathOf(F::Params);
    std::string text;
    if (!addMissing && !fs::exists(file)) {
        return std::nullopt;
    }
    if (fs::exists(file)) {
        if (auto error = readText(file, text)) {
            return error;
        }
    }
    std::string updated = withParameters(text, values, addMissing);
    if (!addMissing && updated == text) {
        return std::nullopt;
    }
    return write(F::Params, updated);
}

std::optional<Message> MachineFolder::saveToolTable(const tools::ToolTable& table,
                                                        const std::map<int, double>& zParameters,
                                                        const files::AtomicWriteHooks& hooks,
                                                        const std::map<int, double>& parameters) const {
    if (folder_.empty()) {
        return message("folder_none_tool_table");
    }
    if (auto error = finishInterruptedChange()) {
        return error;
    }
    const std::string tableText = tools::formatToolTable(table);
    const fs::path paramsFile = pathOf(F::Params);
    std::string text;
    if (fs::exists(paramsFile)) {
        if (auto error = readText(paramsFile, text)) {
            return error;
        }
    }
    std::string updated = withParameters(text, zParameters, false);
    if (!parameters.empty()) {
        updated = withParameters(updated, parameters, true);
    }
    if (updated == text) {
        return write(F::ToolTable, tableText, hooks);
    }
    // one change: a crash between the two files left T1's Z new in one and old in the other, and
    // the older value won at the next start
    const std::array change{files::ChangedFile{pathOf(F::ToolTable), tableText, true},
                            files::ChangedFile{paramsFile, updated, true}};
    return files::writeTogether(folder_ / kChangeJournal, change, hooks);
}

std::optional<Message> MachineFolder::finishInterruptedChange() const {
    if (folder_.empty()) {
        return std::nullopt;
    }
    std::vector<fs::path> candidates;
    for (const FolderFileInfo& info : kFiles) {
        if (info.how == W::KeepingLastGood) {
            candidates.push_back(pathOf(info.file));
        }
    }
    return files::finishInterruptedChange(folder_ / kChangeJournal, candidates);
}

std::optional<Message> MachineFolder::saveToolLife(const tools::LifeData& data,
                                                       const files::AtomicWriteHooks& hooks) const {
    return write(F::ToolLife, tools::formatToolLife(data), hooks);
}

std::optional<Message> MachineFolder::exportToolTable(const fs::path& target, const tools::ToolTable& table) const {
    if (auto refused = refuseFolderFile(target)) {
        return refused;
    }
    if (auto why = files::unwritableOutput(target)) {
        return files::describeUnwritable(bilingual("the tool table export", "刀具表导出"), target, *why);
    }
    // a device or FIFO the operator names is written as one, a file replaced whole
    return files::writeOutputFile(target, tools::formatToolTable(table));
}

bool MachineFolder::isFolderFile(const fs::path& path) const {
    if (folder_.empty() || path.empty()) {
        return false;
    }
    const fs::path file = resolved(path);
    if (file.parent_path() != resolved(folder_)) {
        return false;
    }
    std::string name = file.filename().string();
    const std::string lastGood = files::lastGoodPath("").string();
    if (endsWith(name, lastGood) && name.size() > lastGood.size()) {
        name.resize(name.size() - lastGood.size());
    }
    const std::string pending = files::pendingPath("").string();
    if (endsWith(name, pending) && name.size() > pending.size()) {
        name.resize(name.size() - pending.size());
    }
    if (name == kChangeJournal) {
        return true;
    }
    for (const FolderFileInfo& info : kFiles) {
        if (name == info.name) {
            return true;
        }
    }
    return isHookFile(name);
}

std::optional<Message> MachineFolder::refuseFolderFile(const fs::path& path) const {
    if (!isFolderFile(path)) {
        return std::nullopt;
    }
    return message("folder_file_refused", {path.string(), folder_.string()});
}

} // namespace m350::config
