#include "core/backup/BackupImport.h"

#include "core/files/AtomicFile.h"
#include "core/files/MachineFileRead.h"
#include "core/backup/BackupMachineToml.h"
#include "core/backup/BackupParamsToml.h"
#include "core/backup/BackupPrograms.h"
#include "core/config/HookFiles.h"
#include "core/config/MachineConfig.h"
#include "core/config/MachineFolder.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

namespace m350::backup {

namespace fs = std::filesystem;

namespace {

// A file of the machine folder the import makes: its bytes, or the backup's file it is a copy of
// (copied streaming, compared a chunk at a time: a .nc of 270 MB took 5 GB when read whole).
struct FolderFile {
    std::string name; // in the folder
    std::string bytes;
    std::optional<fs::path> source;
};
using Files = std::vector<FolderFile>; // in write order

constexpr std::size_t kCopyChunk = 1 << 20;

// Whether the file at `a` holds `bytes` (or the same bytes as the file at `b`); false when either
// cannot be read as a regular file.
bool sameContent(const fs::path& a, const FolderFile& b) {
    std::error_code ec;
    if (!fs::is_regular_file(a, ec)) {
        return false;
    }
    if (!b.source) {
        std::string text;
        return !files::readMachineFile(a, text, b.bytes.size()) && text == b.bytes;
    }
    if (!fs::is_regular_file(*b.source, ec) || fs::file_size(a, ec) != fs::file_size(*b.source, ec)) {
        return false;
    }
    std::ifstream left(a, std::ios::binary);
    std::ifstream right(*b.source, std::ios::binary);
    std::string x(kCopyChunk, '\0'), y(kCopyChunk, '\0');
    while (left && right) {
        left.read(x.data(), static_cast<std::streamsize>(x.size()));
        right.read(y.data(), static_cast<std::streamsize>(y.size()));
        if (left.gcount() != right.gcount() ||
            std::memcmp(x.data(), y.data(), static_cast<std::size_t>(left.gcount())) != 0) {
            return false;
        }
    }
    return !left.bad() && !right.bad() && left.eof() && right.eof();
}

// `source` copied to `target` a chunk at a time, then synced; nullopt on success, else why.
std::optional<Message> copyStreaming(const fs::path& source, const fs::path& target) {
    std::ifstream in(source, std::ios::binary);
    if (!in) {
        return message("file_cannot_read_os", {source.string(), std::strerror(errno)});
    }
    std::ofstream out(target, std::ios::binary | std::ios::trunc);
    if (!out) {
        return message("file_cannot_write_os", {target.string(), std::strerror(errno)});
    }
    std::string chunk(kCopyChunk, '\0');
    while (in) {
        in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        out.write(chunk.data(), in.gcount());
    }
    out.flush();
    if (in.bad()) {
        return message("file_cannot_read_at", {source.string()});
    }
    if (!out) {
        return message("file_cannot_write_at", {target.string()});
    }
    out.close();
    const int fd = ::open(target.c_str(), O_RDONLY | O_CLOEXEC);
    const bool synced = fd >= 0 && ::fsync(fd) == 0;
    if (fd >= 0) {
        ::close(fd);
    }
    return synced ? std::nullopt : std::optional<Message>(message("file_cannot_sync_at", {target.string()}));
}

struct Refusal {
    ImportError error;
};

[[noreturn]] void refuse(std::string code, const fs::path& file, Message words) {
    throw Refusal{{std::move(code), file.string(), std::move(words)}};
}

// Everything the machine folder will hold, and what the import says of it.
Files plan(const ControllerBackup& backup, const params::ParameterCatalogue& catalogue, MessageLanguage language,
           BackupImport& result) {
    Files files;
    ImportedMachine machine = formatImportedMachine(backup);
    files.push_back({std::string(config::MachineFolder::fileName(config::FolderFile::Machine)), machine.text, std::nullopt});
    result.magazine = machine.magazine;
    result.libraries = machine.libraries;
    result.review = std::move(machine.review);
    result.unsupported = std::move(machine.unsupported);

    ImportedParams params = formatImportedParams(backup, catalogue);
    files.push_back({std::string(config::MachineFolder::fileName(config::FolderFile::Params)), params.text, std::nullopt});
    result.parameters = params::ParameterTable::kCount;
    result.factoryCompared = backup.defaultSetting.has_value();
    result.changedParameters = std::move(params.changed);
    result.outOfRange = std::move(params.outOfRange);
    if (!backup.defaultSetting) {
        result.notes.push_back(message("import_note_no_default", {"default_setting"}));
    }
    if (backup.coordinate) {
        files.push_back({std::string(config::MachineFolder::fileName(config::FolderFile::Offsets)),
                         formatImportedOffsets(*backup.coordinate), std::nullopt});
        result.offsets = true;
    } else {
        result.notes.push_back(message("import_note_no_coordinate", {"coordinate"}));
    }
    if (backup.mdiblock) {
        ImportedMdi mdi = importMdiBlock(*backup.mdiblock);
        files.push_back({std::string(config::MachineFolder::fileName(config::FolderFile::MdiBlock)), mdi.bytes, std::nullopt});
        result.mdiLines = std::move(mdi.lines);
        if (mdi.note) {
            result.notes.push_back(*mdi.note);
        }
    } else {
        result.notes.push_back(message("import_note_no_mdiblock", {"mdiblock"}));
    }
    for (const BackupFile& program : backup.programs) {
        files.push_back({program.name, {}, program.source});
        result.copied.push_back(program.name);
        const config::HookFile* hook = program.name.find('/') == std::string::npos ? config::findHook(program.name) : nullptr;
        if (hook && hook->runnable) {
            result.hooks.push_back(message("import_hook", {program.name, config::runsWhenWords(*hook)}));
        }
    }
    result.skipped = backup.skipped;
    result.diagnostics = checkPrograms(backup, result.libraries);
    for (const FolderFile& file : files) {
        result.written.push_back(file.name);
    }
    result.written.push_back(kImportReportFile);
    files.push_back({kImportReportFile, formatImportReport(result, language), std::nullopt});
    return files;
}

bool inside(const fs::path& folder, const fs::path& path) {
    const fs::path base = fs::weakly_canonical(folder);
    const fs::path target = fs::weakly_canonical(path);
    auto [end, ignored] = std::mismatch(base.begin(), base.end(), target.begin(), target.end());
    return end == base.end();
}

// Whether `into` may receive the import: true when it already holds exactly this import (its report
// in either language: `otherReport`).
bool alreadyImported(const fs::path& into, const Files& files, const std::string& otherReport) {
    if (!fs::exists(into)) {
        return false;
    }
    if (!fs::is_directory(into)) {
        refuse("machine_folder_not_empty", into, message("import_is_a_file"));
    }
    if (fs::is_empty(into)) {
        return false;
    }
    std::string differing;
    std::string differingZh;
    int count = 0;
    for (const FolderFile& file : files) {
        if (sameContent(into / file.name, file) ||
            (file.name == kImportReportFile && sameContent(into / file.name, {file.name, otherReport, std::nullopt}))) {
            continue;
        }
        if (++count <= 3) {
            std::error_code ec;
            const bool there = fs::exists(fs::symlink_status(into / file.name, ec));
            differing += (differing.empty() ? "" : ", ") + file.name + (there ? " differs" : " is missing");
            differingZh += (differingZh.empty() ? "" : "，") + (there ? file.name + "内容不同" : "缺少" + file.name);
        }
    }
    if (count > 0) {
        refuse("machine_folder_not_empty", into,
               message("import_not_empty", {bilingual(differing + (count > 3 ? ", ..." : ""),
                                                      differingZh + (count > 3 ? "，……" : ""))}));
    }
    return true;
}

// Writes every file into a temp folder beside `into`, checks that it loads as a machine folder,
// then renames it into place (over an empty folder, which rename replaces).
void writeFolder(const fs::path& into, const Files& files) {
    const fs::path parent = into.parent_path();
    fs::create_directories(parent);
    const fs::path temp = parent / ("." + into.filename().string() + ".import-tmp");
    fs::remove_all(temp);
    fs::create_directory(temp);
    auto abandon = [&temp](const fs::path& file, Message words) {
        std::error_code ignored;
        fs::remove_all(temp, ignored);
        refuse("file_error", file, std::move(words));
    };
    for (const FolderFile& each : files) {
        const fs::path file = temp / each.name;
        fs::create_directories(file.parent_path());
        if (auto error = each.source ? copyStreaming(*each.source, file) : files::writeFileAtomically(file, each.bytes)) {
            abandon(into / each.name, message("import_write_failed", {bilingual(*error)}));
        }
    }
    auto loaded = config::loadMachineFolder(temp.string());
    if (auto* error = std::get_if<config::ConfigError>(&loaded)) {
        abandon(into, message("import_does_not_load", {bilingual(error->message)}));
    }
    std::error_code renamed;
    fs::rename(temp, into, renamed);
    if (renamed) {
        abandon(into, message("import_cannot_move", {renamed.message()}));
    }
    if (auto error = files::syncFolder(parent)) {
        refuse("file_error", parent, message("import_sync_failed", {bilingual(*error)}));
    }
}

} // namespace

std::variant<BackupImport, ImportError> importControllerBackup(const fs::path& backupFolder, const fs::path& into,
                                                               MessageLanguage reportLanguage) {
    const auto& loadedCatalogue = params::ParameterCatalogue::bundled();
    if (auto* error = std::get_if<std::string>(&loadedCatalogue)) {
        return ImportError{"file_error", params::ParameterCatalogue::bundledPath(),
                           message("import_catalogue_unreadable", {*error})};
    }
    const params::ParameterCatalogue& catalogue = std::get<params::ParameterCatalogue>(loadedCatalogue);
    auto read = readControllerBackup(backupFolder, &catalogue);
    if (auto* error = std::get_if<BackupError>(&read)) {
        return ImportError{"backup_error", error->file, error->message};
    }
    const ControllerBackup& backup = std::get<ControllerBackup>(read);
    fs::path target = fs::absolute(into).lexically_normal();
    if (!target.has_filename()) {
        target = target.parent_path();
    }
    BackupImport result;
    try {
        if (inside(backupFolder, target)) {
            refuse("machine_folder_not_empty", into, message("import_inside_backup"));
        }
        const Files files = plan(backup, catalogue, reportLanguage, result);
        const MessageLanguage other =
            reportLanguage == MessageLanguage::Chinese ? MessageLanguage::English : MessageLanguage::Chinese;
        result.unchanged = alreadyImported(target, files, formatImportReport(result, other));
        if (!result.unchanged) {
            writeFolder(target, files);
        }
    } catch (const Refusal& refusal) {
        return refusal.error;
    } catch (const fs::filesystem_error& e) {
        return ImportError{"file_error", e.path1().empty() ? into.string() : e.path1().string(),
                           message("config_system_error", {e.code().message()})};
    }
    result.machineFolder = target.string();
    return result;
}

} // namespace m350::backup
