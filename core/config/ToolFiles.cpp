#include "core/config/ToolFiles.h"

#include "core/config/MachineFolder.h"
#include "core/config/TomlReading.h"
#include "core/files/LastGoodCopy.h"
#include "core/files/MachineFileRead.h"
#include "core/tools/ToolData.h"
#include "core/tools/ToolLifeFile.h"
#include "core/tools/ToolTableFile.h"
#include "core/tools/ToolTableText.h"

#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace m350::config {

namespace fs = std::filesystem;

namespace {

using namespace toml_reading;

// "file: warning: the lines above were not read (its last good copy: ...)"
Message toolFileLinesNotRead(const fs::path& file) {
    return warningIn(file, message("config_lines_not_read", {files::lastGoodPath(file).string()}));
}

} // namespace

// tool.tbl: a refused line is a warning (the rest loads). On the M350 the table's Z replaces the
// tool's parameter; a different non-zero value in params.toml is said.
void loadToolTable(const fs::path& folder, MachineConfig& config) {
    fs::path file = folder / MachineFolder::fileName(FolderFile::ToolTable);
    if (!fs::exists(file)) {
        return;
    }
    std::string text;
    if (auto why = files::readMachineFile(file, text)) {
        fail(file, message("config_tool_table_unreadable", {bilingual(*why)}));
    }
    tools::ParsedToolTable parsed = tools::parseToolTable(text, file.string());
    for (const tools::ToolTableIssue& issue : parsed.issues) {
        config.warn(tools::formatIssue(issue), tools::formatIssue(issue, MessageLanguage::Chinese));
    }
    if (parsed.issues.empty()) {
        files::refreshLastGood(file);
    } else if (!files::lastGoodNote(file).empty()) {
        config.warn(toolFileLinesNotRead(file));
    }
    const std::vector<tools::ToolTable::Line>& lines = parsed.table.lines();
    for (std::size_t i = 0; config.dialect->id == gcode::DialectId::M350 && i < lines.size(); ++i) {
        const std::optional<tools::ToolEntry>& row = lines[i].entry;
        std::optional<int> parameter = row ? tools::m350ZParameter(row->tool, config.parameters) : std::nullopt;
        if (!parameter || !row->offsets[tools::kZ]) {
            continue;
        }
        const double inParams = config.parameters.get(*parameter);
        if (inParams != 0.0 && inParams != *row->offsets[tools::kZ]) {
            config.warn(warningIn(folder / MachineFolder::fileName(FolderFile::Params),
                                  message("config_z_mismatch",
                                          {std::to_string(*parameter), std::to_string(row->tool), tools::tableNumber(inParams),
                                           file.string(), std::to_string(i + 1),
                                           tools::tableNumber(*row->offsets[tools::kZ])})));
        }
    }
    config.toolTable = std::move(parsed.table);
    config.toolTableFile = file.string();
}

void loadToolLifeFile(const fs::path& folder, MachineConfig& config) {
    tools::LifeData lifeSettings;
    if (config.dialect->id == gcode::DialectId::Fanuc) {
        lifeSettings.applyFanucParameters(config.fanucParameters);
    }
    auto life = tools::loadToolLife(folder.string(), lifeSettings.fromParameters ? &lifeSettings : nullptr);
    if (auto* unreadable = std::get_if<Message>(&life)) {
        fail(folder / MachineFolder::fileName(FolderFile::ToolLife),
             message("config_tool_life_unreadable", {bilingual(*unreadable)}));
    }
    tools::ParsedToolLife& parsed = std::get<tools::ParsedToolLife>(life);
    for (const tools::LifeFileIssue& issue : parsed.issues) {
        config.warn(issue.text(), issue.text(MessageLanguage::Chinese));
    }
    const fs::path lifeFile = folder / MachineFolder::fileName(FolderFile::ToolLife);
    if (parsed.issues.empty()) {
        files::refreshLastGood(lifeFile);
    } else if (!files::lastGoodNote(lifeFile).empty()) {
        config.warn(toolFileLinesNotRead(lifeFile));
    }
    config.toolLife = std::move(parsed.data);
    config.toolLifeIssues = std::move(parsed.issues);
}

} // namespace m350::config
