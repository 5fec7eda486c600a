#pragma once

#include "core/backup/BackupWiring.h"
#include "core/backup/ControllerBackup.h"
#include "core/gcode/Diagnostic.h"

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

namespace m350::backup {

// What an import of a controller backup made (or found already made).
struct BackupImport {
    std::string machineFolder;
    bool unchanged = false;            // the folder already held this very import: nothing written
    std::vector<std::string> written;  // the machine folder's files, in the order written
    std::vector<std::string> copied;   // the .nc files among them, byte for byte as in the backup
    std::vector<SkippedFile> skipped;  // files of the backup the simulator does not use
    std::vector<std::string> libraries;
    std::vector<Message> hooks;        // "T.nc: a T word set from the panel ...": the hook files it has
    int parameters = 0;                // written to params.toml
    bool factoryCompared = false;      // the backup had default_setting
    std::vector<int> changedParameters; // differ from default_setting
    std::vector<Message> outOfRange;   // values the panel would refuse, kept as the controller had them
    bool offsets = false;              // offsets.toml written from `coordinate`
    std::vector<std::string> mdiLines; // the six MDI lines, UTF-8 (empty when there was no mdiblock)
    Message magazine;                  // what became of param 802
    std::vector<ReviewItem> review;    // stated values the owner should check in machine.toml
    std::vector<Message> unsupported;  // what the simulator cannot model, plainly
    std::vector<Message> notes;        // other things the import noticed (a missing coordinate ...)
    std::vector<gcode::Diagnostic> diagnostics; // syntax errors in the copied .nc files
};

struct ImportError {
    std::string code; // "backup_error", "machine_folder_not_empty", "file_error"
    std::string file;
    Message message; // by id: said in the CLI's --lang and the panel's language
};

// The report an import writes into the machine folder beside what it made, in the language of the
// import that made it (its first line says which).
inline constexpr const char* kImportReportFile = "import-report.txt";

// Makes `into` a machine folder from the backup folder. Deterministic: the folder's files depend
// only on the backup's content, so importing the same backup twice gives the same bytes. `into`
// may be missing or empty; if it holds exactly this import already, nothing is written and
// `unchanged` says so; any other content (a different backup, or files changed since) is refused
// and left alone. Everything is written into a temp folder beside `into`, checked to load, and
// renamed into place at the end, so a damaged backup or a failure leaves nothing behind.
// import-report.txt is written in `reportLanguage` (the CLI's --lang, the panel's language); a
// folder holding this import with its report in the other language is this import all the same.
std::variant<BackupImport, ImportError> importControllerBackup(const std::filesystem::path& backup,
                                                               const std::filesystem::path& into,
                                                               MessageLanguage reportLanguage);

// The human report in `language`: what was made, what to review, what the simulator cannot model,
// and the syntax errors of the copied files; its first line names the language. No paths, no
// times: the same backup gives the same text. File names, keys and G-code stay as they are.
std::string formatImportReport(const BackupImport& result, MessageLanguage language);

} // namespace m350::backup
