#include "core/backup/BackupImport.h"

#include "core/files/AtomicFile.h"
#include "core/backup/BackupMachineToml.h"
#include "core/backup/BackupParamsToml.h"
#include "core/backup/BackupPrograms.h"
#include "core/config/HookFiles.h"
#include "core/config/MachineConfig.h"
#include "core/config/MachineFolder.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <utility>

namespace m350::backup {

namespace fs = std::filesystem;

namespace {

using Files = std::vector<std::pair<std::string, std::string>>; // name in the folder, bytes; in write order

struct Refusal {
    ImportError error;
};

[[noreturn]] void refuse(std::string code, const fs::path& file, std::string message) {
    throw Refusal{{std::move(code), file.string(), std::move(message)}};
}

// Everything the machine folder will hold, and what the import says of it.
Files plan(const ControllerBackup& backup, const params::ParameterCatalogue& catalogue, BackupImport& result) {
    Files files;
    ImportedMachine machine = formatImportedMachine(backup);
    files.emplace_back(config::MachineFolder::fileName(config::FolderFile::Machine), machine.text);
    result.magazine = machine.magazine;
    result.libraries = machine.libraries;
    result.review = std::move(machine.review);
    result.unsupported = std::move(machine.unsupported);

    ImportedParams params = formatImportedParams(backup, catalogue);
    files.emplace_back(config::MachineFolder::fileName(config::FolderFile::Params), params.text);
    result.parameters = params::ParameterTable::kCount;
    result.factoryCompared = backup.defaultSetting.has_value();
    result.changedParameters = std::move(params.changed);
    result.outOfRange = std::move(params.outOfRange);
    if (!backup.defaultSetting) {
        result.notes.push_back("no default_setting: no parameter is compared with the factory values");
    }
    if (backup.coordinate) {
        files.emplace_back(config::MachineFolder::fileName(config::FolderFile::Offsets), formatImportedOffsets(*backup.coordinate));
        result.offsets = true;
    } else {
        result.notes.push_back("no coordinate file: every work offset is 0");
    }
    if (backup.mdiblock) {
        ImportedMdi mdi = importMdiBlock(*backup.mdiblock);
        files.emplace_back(config::MachineFolder::fileName(config::FolderFile::MdiBlock), mdi.bytes);
        result.mdiLines = std::move(mdi.lines);
        if (mdi.note) {
            result.notes.push_back(*mdi.note);
        }
    } else {
        result.notes.push_back("no mdiblock: the MDI page starts with six empty lines");
    }
    for (const BackupFile& program : backup.programs) {
        files.emplace_back(program.name, program.bytes);
        result.copied.push_back(program.name);
        const config::HookFile* hook = program.name.find('/') == std::string::npos ? config::findHook(program.name) : nullptr;
        if (hook && hook->runnable) {
            result.hooks.push_back(program.name + ": " + std::string(hook->runsWhen));
        }
    }
    result.skipped = backup.skipped;
    result.diagnostics = checkPrograms(backup, result.libraries);
    for (const auto& file : files) {
        result.written.push_back(file.first);
    }
    result.written.push_back(kImportReportFile);
    files.emplace_back(kImportReportFile, formatImportReport(result));
    return files;
}

std::optional<std::string> contentOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        return std::nullopt;
    }
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

bool inside(const fs::path& folder, const fs::path& path) {
    const fs::path base = fs::weakly_canonical(folder);
    const fs::path target = fs::weakly_canonical(path);
    auto [end, ignored] = std::mismatch(base.begin(), base.end(), target.begin(), target.end());
    return end == base.end();
}

// Whether `into` may receive the import: true when it already holds exactly this import.
bool alreadyImported(const fs::path& into, const Files& files) {
    if (!fs::exists(into)) {
        return false;
    }
    if (!fs::is_directory(into)) {
        refuse("machine_folder_not_empty", into, "is a file, not a folder; nothing written");
    }
    if (fs::is_empty(into)) {
        return false;
    }
    std::string differing;
    int count = 0;
    for (const auto& [name, bytes] : files) {
        std::optional<std::string> existing = contentOf(into / name);
        if (existing == bytes) {
            continue;
        }
        if (++count <= 3) {
            differing += (differing.empty() ? "" : ", ") + name + (existing ? " differs" : " is missing");
        }
    }
    if (count > 0) {
        refuse("machine_folder_not_empty", into,
               "is not empty and does not hold this backup's import (" + differing + (count > 3 ? ", ..." : "") +
                   "); nothing written: choose a new or empty folder");
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
    auto abandon = [&temp](const fs::path& file, std::string message) {
        std::error_code ignored;
        fs::remove_all(temp, ignored);
        refuse("file_error", file, std::move(message));
    };
    for (const auto& [name, bytes] : files) {
        const fs::path file = temp / name;
        fs::create_directories(file.parent_path());
        if (auto error = files::writeFileAtomically(file, bytes)) {
            abandon(into / name, *error + "; nothing written");
        }
    }
    auto loaded = config::loadMachineFolder(temp.string());
    if (auto* error = std::get_if<config::ConfigError>(&loaded)) {
        abandon(into, "the imported folder does not load (" + error->message + "); nothing written");
    }
    std::error_code renamed;
    fs::rename(temp, into, renamed);
    if (renamed) {
        abandon(into, "cannot move the import into place: " + renamed.message() + "; nothing written");
    }
    if (auto error = files::syncFolder(parent)) {
        refuse("file_error", parent, *error);
    }
}

} // namespace

std::variant<BackupImport, ImportError> importControllerBackup(const fs::path& backupFolder, const fs::path& into) {
    const auto& loadedCatalogue = params::ParameterCatalogue::bundled();
    if (auto* error = std::get_if<std::string>(&loadedCatalogue)) {
        return ImportError{"file_error", params::ParameterCatalogue::bundledPath(), *error};
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
            refuse("machine_folder_not_empty", into, "lies inside the backup folder; nothing written");
        }
        const Files files = plan(backup, catalogue, result);
        result.unchanged = alreadyImported(target, files);
        if (!result.unchanged) {
            writeFolder(target, files);
        }
    } catch (const Refusal& refusal) {
        return refusal.error;
    } catch (const fs::filesystem_error& e) {
        return ImportError{"file_error", e.path1().empty() ? into.string() : e.path1().string(), e.code().message()};
    }
    result.machineFolder = target.string();
    return result;
}

} // namespace m350::backup
