#include "core/backup/BackupPrograms.h"

#include "core/gcode/Parser.h"
#include "core/gcode/SourceText.h"

#include <algorithm>

namespace m350::backup {

namespace {

constexpr std::size_t kRecords = 6;
constexpr std::size_t kRecordBytes = kMdiBlockBytes / kRecords;

gcode::FileRole libraryRole(const std::string& name) {
    return sameNameAnyCase(name, "slib-m.nc") ? gcode::FileRole::MLibrary
                                              : gcode::FileRole::GLibrary; // slib-g.nc, slibuser.nc
}

// Parses `files` into one program and keeps the syntax errors (the findings that stop a run). Each
// is read where it lies (mapped) as `check` reads it: a program of hundreds of MB (one parsed alone,
// as the program to run) stays out of memory but for what jumps and calls need.
void parseTogether(const std::vector<const BackupFile*>& files, std::vector<gcode::Diagnostic>& out, bool alone) {
    gcode::Program program;
    gcode::Parser parser(gcode::Dialect::m350());
    for (const BackupFile* file : files) {
        auto source = gcode::readSourceFile(file->source.string());
        if (auto* error = std::get_if<gcode::SourceReadError>(&source)) {
            out.push_back({gcode::Severity::Error, gcode::DiagnosticKind::Syntax, file->name, error->line,
                           error->column, error->message});
            continue;
        }
        auto& text = std::get<gcode::SourceText>(source);
        text.path = file->name; // its findings name it as the backup does
        parser.addSource(program, text, alone ? gcode::FileRole::Main : libraryRole(file->name));
    }
    for (const gcode::Diagnostic& d : parser.diagnostics()) {
        if (d.severity == gcode::Severity::Error && d.kind == gcode::DiagnosticKind::Syntax) {
            out.push_back(d);
        }
    }
}

} // namespace

ImportedMdi importMdiBlock(const std::string& raw) {
    ImportedMdi mdi;
    mdi.bytes.assign(kMdiBlockBytes, '\0');
    bool tidied = false;
    for (std::size_t i = 0; i < kRecords; ++i) {
        std::string record = i * kRecordBytes < raw.size() ? raw.substr(i * kRecordBytes, kRecordBytes) : std::string();
        const std::size_t end = std::min(record.find('\0'), kRecordBytes - 1); // the panel keeps a NUL at the end
        tidied |= record.find_first_not_of('\0', end) != std::string::npos;
        std::string line = record.substr(0, end);
        mdi.bytes.replace(i * kRecordBytes, line.size(), line);
        auto decoded = gcode::decodeSource("mdiblock", line);
        if (auto* text = std::get_if<gcode::SourceText>(&decoded)) {
            mdi.lines.emplace_back(text->text);
        } else {
            mdi.lines.emplace_back();
            mdi.note = message("import_mdi_undecodable", {"mdiblock", std::to_string(i + 1)});
        }
    }
    if (raw.size() != kMdiBlockBytes) {
        mdi.note = message("import_mdi_size", {"mdiblock", std::to_string(raw.size()), std::to_string(kMdiBlockBytes)});
    } else if (tidied && !mdi.note) {
        mdi.note = message("import_mdi_after_end", {"mdiblock"});
    }
    return mdi;
}

std::vector<gcode::Diagnostic> checkPrograms(const ControllerBackup& backup, const std::vector<std::string>& libraries) {
    std::vector<gcode::Diagnostic> found;
    std::vector<const BackupFile*> libraryFiles;
    for (const BackupFile& file : backup.programs) {
        if (std::find(libraries.begin(), libraries.end(), file.name) != libraries.end()) {
            libraryFiles.push_back(&file);
        }
    }
    parseTogether(libraryFiles, found, false);
    for (const BackupFile& file : backup.programs) {
        if (std::find(libraries.begin(), libraries.end(), file.name) == libraries.end()) {
            parseTogether({&file}, found, true);
        }
    }
    return found;
}

} // namespace m350::backup
