#include "app/sim/ImportCommand.h"
#include "app/sim/ExitStatus.h"

#include "app/sim/ReportJson.h"

#include "core/backup/BackupImport.h"

#include <nlohmann/json.hpp>

#include <iostream>

namespace m350::sim {

namespace {

std::vector<std::string> english(const std::vector<Message>& messages) {
    std::vector<std::string> texts;
    for (const Message& m : messages) {
        texts.push_back(m.english());
    }
    return texts;
}

// Every key is present whatever happened, so a script can read any of them; texts in English, as
// every message of the JSON (the report on stderr and import-report.txt are in --lang).
nlohmann::json importJson(const backup::BackupImport& r, const backup::ImportError* error) {
    nlohmann::json skipped = nlohmann::json::array();
    for (const backup::SkippedFile& file : r.skipped) {
        skipped.push_back({{"file", file.name}, {"reason", file.reason.english()}});
    }
    nlohmann::json review = nlohmann::json::array();
    for (const backup::ReviewItem& item : r.review) {
        review.push_back({{"key", item.key}, {"value", argumentIn(item.value, MessageLanguage::English)}, {"why", item.why.english()}});
    }
    nlohmann::json alarm = nullptr;
    if (error) {
        alarm = {{"code", error->code}, {"message", error->message.english()}, {"message_id", error->message.id},
                 {"file", error->file}, {"line", 0}, {"column", 0}};
    }
    return {{"status", error ? "error" : "ok"},
            {"alarm", alarm},
            {"machine_folder", error ? nlohmann::json(nullptr) : nlohmann::json(r.machineFolder)},
            {"unchanged", r.unchanged},
            {"written", r.written},
            {"copied", r.copied},
            {"skipped", skipped},
            {"libraries", r.libraries},
            {"hooks", english(r.hooks)},
            {"parameters", r.parameters},
            {"changed_parameters", r.factoryCompared ? nlohmann::json(r.changedParameters) : nlohmann::json(nullptr)},
            {"out_of_range", english(r.outOfRange)},
            {"offsets", r.offsets},
            {"mdi_lines", r.mdiLines},
            {"magazine", r.magazine.english()},
            {"review", review},
            {"unsupported", english(r.unsupported)},
            {"notes", english(r.notes)},
            {"diagnostics", diagnosticsJson(r.diagnostics)}};
}

} // namespace

int runImport(const std::string& backupDir, const std::string& intoDir, MessageLanguage language) {
    auto outcome = backup::importControllerBackup(backupDir, intoDir, language);
    if (auto* error = std::get_if<backup::ImportError>(&outcome)) {
        std::cerr << error->file << ": " << error->message.in(language) << '\n';
        std::cout << dump(importJson(backup::BackupImport{}, error)) << '\n';
        return kExitError;
    }
    const auto& result = std::get<backup::BackupImport>(outcome);
    if (result.unchanged) {
        std::cerr << message("import_already_done", {result.machineFolder}).in(language) << '\n';
    } else {
        std::cerr << message("import_done", {backupDir, result.machineFolder}).in(language) << '\n';
    }
    std::cerr << backup::formatImportReport(result, language);
    std::cout << dump(importJson(result, nullptr)) << '\n';
    return kExitOk;
}

} // namespace m350::sim
