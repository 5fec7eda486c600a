#pragma once

#include "core/common/Message.h"
#include "core/controller/RunSettings.h"

#include <optional>
#include <string>
#include <vector>

namespace m350::sim {

// The command line of `m350-sim`, parsed and checked.
struct SimOptions {
    enum class Command { Run, Mdi, Check, Import, Hook, Tools, ResetPasswords } command = Command::Run;
    std::string program;                 // run / check
    std::vector<std::string> mdiLines;   // mdi
    std::string hookName;                // hook: a name of config/HookFiles.h ("fndzero", "key-3")
    std::string configDir;               // empty: the bundled machine for the dialect
    std::string backupDir, intoDir;      // import: the controller backup and the new machine folder
    std::optional<std::string> dialect;
    std::vector<int> printVariables;
    std::optional<std::string> traceFile;
    std::optional<std::string> outputFile; // --dprnt: where POPEN/DPRNT/BPRNT/PCLOS output goes
    bool lint = false;                   // check --lint: the trainee lints (check::TraineeLint) too
    bool home = false;                   // 回零 every axis that has a home switch before the run
    std::optional<std::string> toolTableFile; // --tool-table: instead of the folder's tool.tbl
    std::optional<std::string> toolsOut;      // --tools-out: the tool table after the run
    bool toolsAsTable = false;                // tools --tbl: tool.tbl text instead of JSON
    std::optional<int> confirmTool;           // --confirm-tool: after the run, RESET and enter the spindle's tool
    MessageLanguage language = MessageLanguage::English; // --lang: the alarm lines on stderr
    bool languageGiven = false; // --lang was given: the run's notices are said on stderr too
    controller::RunSettings settings;
};

// Returns the options, or an exit status (0 after --help, 64 for a usage error, message printed).
struct ParseOutcome {
    std::optional<SimOptions> options;
    int exitStatus = 0;
};
ParseOutcome parseCommandLine(int argc, char** argv);

} // namespace m350::sim
