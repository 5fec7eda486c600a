#include "core/config/MachineConfig.h"

#include "core/common/ResourceDirectory.h"
#include "core/config/MachineFolder.h"
#include "core/config/MachineToml.h"
#include "core/config/ModbusSlaves.h"
#include "core/config/OffsetsToml.h"
#include "core/config/ParamsToml.h"
#include "core/config/TomlReading.h"
#include "core/config/ToolFiles.h"
#include "core/config/VariablesToml.h"
#include "core/files/LastGoodCopy.h"
#include "core/tools/SpindleLoadLimits.h"

#include <filesystem>

namespace m350::config {

namespace fs = std::filesystem;

namespace {

using toml_reading::fail;
using toml_reading::Failure;

} // namespace

std::variant<MachineConfig, ConfigError> loadMachineFolder(const std::string& folder) {
    MachineConfig config;
    fs::path dir(folder);
    config.folder = folder;
    try {
        if (!fs::is_directory(dir)) {
            fail(dir, message("config_not_a_folder"));
        }
        // a save a crash interrupted is finished (or dropped) before any file is read
        if (auto broken = MachineFolder(dir).finishInterruptedChange()) {
            fail(dir / MachineFolder::kChangeJournal, message("config_journal_broken", {bilingual(*broken)}));
        }
        loadMachineToml(dir, config);
        loadParams(dir, config);
        loadOffsets(dir, config);
        loadVariables(dir, config);
        if (auto wrong = loadModbusSlaves((dir / MachineFolder::fileName(FolderFile::Modbus)).string(), config.modbus)) {
            fail(dir / MachineFolder::fileName(FolderFile::Modbus), *wrong);
        }
        loadToolTable(dir, config);
        loadToolLifeFile(dir, config);
        if (auto wrong = tools::readLoadMonitorSettings((dir / tools::kSpindleLoadFileName).string(), config.loadMonitor)) {
            return ConfigError{(dir / tools::kSpindleLoadFileName).string(), message("config_spindle_load_wrong", {bilingual(wrong->message)}),
                               wrong->line, wrong->column};
        }
        files::refreshLastGood(dir / MachineFolder::fileName(FolderFile::Params));
    } catch (const Failure& f) {
        ConfigError error = f.error;
        if (!files::lastGoodNote(error.file).empty()) {
            error.message = message("config_last_good", {bilingual(error.message), files::lastGoodPath(error.file).string()});
        }
        return error;
    } catch (const fs::filesystem_error& e) {
        // a symlink loop, a dangling link, a folder that cannot be listed: an error, not an abort
        return ConfigError{e.path1().empty() ? folder : e.path1().string(), message("config_system_error", {e.code().message()})};
    }
    return config;
}

std::string ConfigError::where() const {
    if (line <= 0) {
        return file;
    }
    return file + ":" + std::to_string(line) + (column > 0 ? ":" + std::to_string(column) : std::string());
}

std::string ConfigError::text(MessageLanguage language) const {
    return where() + ": " + message.in(language);
}

std::string bundledMachinesDirectory() {
    return resourceDirectory() + "/machines";
}

} // namespace m350::config
