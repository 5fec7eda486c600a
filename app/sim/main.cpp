// m350-sim: the headless simulator. Exit status: 0 ok, 1 alarm, 2 error (syntax, file, config),
// 64 usage.
#include "app/sim/ExitStatus.h"
#include "app/sim/HookCommand.h"
#include "app/sim/ImportCommand.h"
#include "app/sim/OutputPaths.h"
#include "app/sim/ReportJson.h"
#include "app/sim/ResetPasswordsCommand.h"
#include "app/sim/SimOptions.h"
#include "app/sim/ToolsCommand.h"
#include "app/sim/ToolLifeJson.h"
#include "app/sim/SpindleLoadJson.h"

#include "core/check/StaticCheck.h"
#include "core/check/TraineeLint.h"
#include "core/config/CallCodeParameters.h"
#include "core/params/FanucParameters.h"
#include "core/files/OutputFile.h"
#include "core/config/MachineConfig.h"
#include "core/config/MachineFolder.h"
#include "core/params/ParameterNumbers.h"
#include "core/controller/Controller.h"
#include "core/macro/VariableMap.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>

namespace {

using namespace m350;
using sim::kExitAlarm;
using sim::kExitError;
using sim::kExitOk;
using sim::kExitUsage;

std::string machineFolder(const sim::SimOptions& o) {
    if (!o.configDir.empty()) {
        return o.configDir;
    }
    std::string name = o.dialect && *o.dialect == "fanuc" ? "fanuc-0i" : config::kDefaultMachine;
    return config::bundledMachinesDirectory() + "/" + name;
}

void printDiagnostics(const std::vector<gcode::Diagnostic>& diagnostics, MessageLanguage language) {
    for (const gcode::Diagnostic& d : diagnostics) {
        std::cerr << gcode::formatDiagnostic(d, language) << '\n';
    }
}

// A tool on the table is in neither `tool` nor `pockets`: said, so nobody counts it as lost.
void printFallenTools(const std::vector<devices::FallenTool>& fallen, MessageLanguage language) {
    for (const devices::FallenTool& f : fallen) {
        char at[96];
        std::snprintf(at, sizeof at, "X%.3f Y%.3f Z%.3f", f.at.x(), f.at.y(), f.at.z());
        std::cerr << "m350-sim: " << messageText("tool_on_table", {std::to_string(f.tool), at}, language) << '\n';
    }
}

// A file the run needs that cannot be had, said in the --lang language; the JSON keeps the
// English and gives the id.
int fail(const std::string& code, const Message& words, const std::string& file, MessageLanguage language) {
    std::cerr << file << ": " << words.in(language) << '\n';
    nlohmann::json j = sim::errorJson(code, words.english(), file);
    j["alarm"]["message_id"] = words.id;
    nlohmann::json arguments = nlohmann::json::array();
    for (const std::string& argument : words.arguments) {
        arguments.push_back(argumentIn(argument, MessageLanguage::English));
    }
    j["alarm"]["message_arguments"] = std::move(arguments);
    std::cout << sim::dump(j) << '\n';
    return kExitError;
}

// check's layout: every finding on stderr, {"status", "diagnostics"} on stdout.
int checkResult(const std::vector<gcode::Diagnostic>& diagnostics, MessageLanguage language) {
    printDiagnostics(diagnostics, language);
    bool errors = false;
    for (const gcode::Diagnostic& d : diagnostics) {
        errors |= d.severity == gcode::Severity::Error;
    }
    nlohmann::json j{{"status", errors ? "error" : "ok"}, {"diagnostics", sim::diagnosticsJson(diagnostics)}};
    std::cout << sim::dump(j) << '\n';
    return errors ? kExitError : kExitOk;
}

int check(controller::Controller& controller, const sim::SimOptions& o) {
    controller.loadFile(o.program);
    std::vector<gcode::Diagnostic> diagnostics = controller.diagnostics();
    if (!gcode::hasBlockingError(diagnostics)) {
        const config::MachineConfig machine = controller.config();
        std::vector<gcode::Diagnostic> findings =
            check::StaticCheck(controller.program(), *machine.dialect, machine.callCodes,
                               {machine.variableLayout, {machine.additionalWorkSystems(), machine.rotation()}})
                .findings();
        diagnostics.insert(diagnostics.end(), findings.begin(), findings.end());
        if (o.lint) {
            if (const std::optional<std::uint32_t> main = controller.program().mainUnit()) {
                std::vector<gcode::Diagnostic> lints =
                    check::TraineeLint(controller.program(), *machine.dialect, machine.variableLayout)
                        .findings(controller.program().units[*main].file);
                diagnostics.insert(diagnostics.end(), lints.begin(), lints.end());
            }
        }
    }
    return checkResult(diagnostics, o.language);
}

// What the command line asks of this machine: a tool it can hold, variables a run may set. Said
// before the run, as a usage error, instead of being dropped or used as garbage.
std::optional<Message> checkAgainstMachine(const sim::SimOptions& o, const config::MachineConfig& machine) {
    if (o.settings.tool) {
        const int tool = *o.settings.tool;
        const bool m350 = machine.dialect->id == gcode::DialectId::M350;
        const int capacity = m350 ? static_cast<int>(machine.parameters.get(param::kMagazineCapacity))
                                  : machine.magazineCapacity;
        const int virtualTools = m350 && machine.parameters.get(param::kVirtualTools) != 0.0 ? 20 : 0;
        const int most = capacity > 0 ? capacity + virtualTools : 9999;
        if (tool < 0 || tool > most) {
            const std::string option = "--tool " + std::to_string(tool);
            if (capacity <= 0) {
                return message("usage_tool_range", {option, std::to_string(most)});
            }
            return message(virtualTools ? "usage_tool_range_virtual" : "usage_tool_range_capacity",
                           {option, std::to_string(most), std::to_string(capacity)});
        }
    }
    macro::VariableMap variables(*machine.dialect, machine.variableLayout);
    for (const auto& [number, value] : o.settings.variables) {
        macro::VariableInfo info = variables.describe(number);
        if (info.kind == macro::VariableKind::Undefined || info.readOnly) {
            return message(info.readOnly ? "usage_var_read_only" : "usage_var_undefined",
                           {"--var " + std::to_string(number), variables.describeWords(number)});
        }
    }
    for (int number : o.printVariables) {
        if (variables.describe(number).kind == macro::VariableKind::Undefined) {
            return message("usage_option", {"--print " + std::to_string(number), bilingual(variables.undefinedWords(number))});
        }
    }
    return std::nullopt;
}

// What the program sent to the external output device (POPEN ... PCLOS), into --dprnt FILE or
// dprnt.txt beside the program, written whole and atomically after the run; what went wrong, if
// anything (said on stderr).
std::optional<std::string> writeExternalOutput(const controller::Controller& controller, const sim::SimOptions& o) {
    if (!controller.externalDevices().outputOpened()) {
        return std::nullopt;
    }
    const std::string file = sim::externalOutputPath(o);
    if (auto problem = files::writeOutputFile(file, controller.externalDevices().received())) {
        std::cerr << "m350-sim: " << messageText("dprnt_cannot_write", {file, bilingual(*problem)}, o.language) << '\n';
        return problem->english();
    }
    std::cerr << "m350-sim: " << messageText("dprnt_written", {file}, o.language) << '\n';
    return std::nullopt;
}

// Tool life data the run used or entered (G10 L3) go back into the machine folder's toollife.txt.
std::optional<std::string> saveToolLife(controller::Controller& controller, const config::MachineFolder& folder,
                                        MessageLanguage language) {
    if (!controller.toolLife().manager().changed()) {
        return std::nullopt;
    }
    if (auto problem = folder.saveToolLife(controller.toolLife().manager().data())) {
        const std::string file =
            folder.path().string() + "/" + std::string(config::MachineFolder::fileName(config::FolderFile::ToolLife));
        std::cerr << "m350-sim: " << messageText("life_data_cannot_write", {file, bilingual(*problem)}, language) << '\n';
        return problem->english();
    }
    controller.toolLife().manager().markSaved();
    return std::nullopt;
}

// A full disk or a closed pipe under stdout must not end the run with status 0.
bool flushedStdout() {
    errno = 0;
    std::cout.flush();
    if (std::cout && std::fflush(stdout) == 0) {
        return true;
    }
    std::cerr << "m350-sim: cannot write the result to stdout: " << std::strerror(errno != 0 ? errno : EIO) << '\n';
    return false;
}

int runCommand(int argc, char** argv) {
    auto parsed = sim::parseCommandLine(argc, argv);
    if (!parsed.options) {
        return parsed.exitStatus;
    }
    sim::SimOptions& o = *parsed.options;
    if (o.command == sim::SimOptions::Command::Import) {
        return sim::runImport(o.backupDir, o.intoDir, o.language);
    }
    if (o.command == sim::SimOptions::Command::ResetPasswords) {
        return sim::runResetPasswords(o.configDir, o.language);
    }
    std::string folder = machineFolder(o);
    auto loaded = config::loadMachineFolder(folder);
    if (auto* error = std::get_if<config::ConfigError>(&loaded)) {
        std::cerr << error->text(o.language) << '\n';
        nlohmann::json j = sim::errorJson("config_error", error->message.english(), error->file, error->line, error->column);
        j["alarm"]["message_id"] = error->message.id;
        nlohmann::json arguments = nlohmann::json::array();
        for (const std::string& argument : error->message.arguments) {
            arguments.push_back(argumentIn(argument, MessageLanguage::English));
        }
        j["alarm"]["message_arguments"] = std::move(arguments);
        std::cout << sim::dump(j) << '\n';
        return kExitError;
    }
    config::MachineConfig machineConfig = std::move(std::get<config::MachineConfig>(loaded));
    for (std::size_t i = 0; i < machineConfig.warnings.size(); ++i) {
        std::cerr << machineConfig.warning(i, o.language) << '\n';
    }
    if (o.dialect) {
        machineConfig.dialect = gcode::Dialect::byName(*o.dialect);
    }
    if (machineConfig.dialect->id == gcode::DialectId::M350) {
        for (const auto& [number, value] : o.settings.parameters) {
            if (params::isFanucParameterNumber(number)) {
                std::cerr << "m350-sim: "
                          << messageText("usage_param_m350",
                                       {"--param " + std::to_string(number),
                                        bilingual(machineConfig.name,
                                                  machineConfig.nameZh.empty() ? machineConfig.name : machineConfig.nameZh)},
                                       o.language)
                          << '\n';
                return kExitUsage;
            }
        }
    }
    if (machineConfig.dialect->id == gcode::DialectId::Fanuc) {
        // --param may make a code call a program (6050-6091): a clash is said before the run
        bool fanucParameters = false;
        for (const auto& [number, value] : o.settings.parameters) {
            if (params::isFanucParameterNumber(number)) {
                machineConfig.fanucParameters[number] = value;
                machineConfig.fanucParameterOrigins[number] = "--param " + std::to_string(number);
                fanucParameters = true;
            }
        }
        if (auto refused = fanucParameters ? config::rebuildCallCodes(machineConfig) : std::nullopt) {
            std::cerr << "m350-sim: --param " << refused->parameter << ": " << refused->message.in(o.language) << '\n';
            return kExitUsage;
        }
    }
    if (auto error = sim::useToolTableFile(o, machineConfig)) {
        return fail("file_error", *error, *o.toolTableFile, o.language);
    }
    if (o.command == sim::SimOptions::Command::Run || o.command == sim::SimOptions::Command::Check) {
        std::error_code ec; // a symlink loop or an unreadable folder is an error, not an abort
        const std::filesystem::file_status status = std::filesystem::status(o.program, ec);
        std::optional<Message> unreadable;
        if (ec || !std::filesystem::exists(status)) {
            unreadable = ec && ec != std::errc::no_such_file_or_directory ? message("program_cannot_open", {ec.message()})
                                                                           : message("program_missing");
        } else if (!std::filesystem::is_regular_file(status)) {
            unreadable = message("program_not_a_file");
        }
        if (unreadable && o.command == sim::SimOptions::Command::Check) {
            return checkResult(
                {gcode::diagnostic(gcode::Severity::Error, gcode::DiagnosticKind::Syntax, o.program, 0, 0, *unreadable)},
                o.language);
        }
        if (unreadable) {
            return fail("file_error", *unreadable, o.program, o.language);
        }
    }
    if (auto refused = sim::outputNamingAnInput(o, machineConfig)) {
        std::cerr << "m350-sim: " << refused->in(o.language) << '\n';
        return kExitUsage;
    }
    std::unique_ptr<files::OutputFile> trace;
    if (o.traceFile) {
        auto opened = files::OutputFile::open(*o.traceFile);
        if (auto* error = std::get_if<Message>(&opened)) {
            return fail("file_error", message("trace_cannot_write", {bilingual(*error)}), *o.traceFile, o.language);
        }
        trace = std::move(std::get<std::unique_ptr<files::OutputFile>>(opened));
        o.settings.trace = &trace->stream();
    }
    if (o.command != sim::SimOptions::Command::Check) {
        if (auto problem = checkAgainstMachine(o, machineConfig)) {
            std::cerr << "m350-sim: " << problem->in(o.language) << "\n";
            return kExitUsage;
        }
        if (auto problem = sim::missingHook(o, machineConfig)) {
            std::cerr << "m350-sim: " << problem->in(o.language) << "\n";
            return kExitUsage;
        }
    }
    const std::vector<tools::LifeFileIssue> lifeIssues = machineConfig.toolLifeIssues;
    controller::Controller controller(std::move(machineConfig), o.settings);
    if (o.command == sim::SimOptions::Command::Check) {
        return check(controller, o);
    }
    if (o.command == sim::SimOptions::Command::Tools) {
        return sim::listTools(controller, o);
    }
    std::optional<controller::RunReport> homing = o.home ? sim::homeBeforeRun(controller) : std::nullopt;
    bool ready = !homing && sim::loadForCommand(controller, o);
    controller::RunReport report = homing ? *homing : controller.run();
    if (!homing && !ready) {
        report.status = controller::RunStatus::Error;
    }
    if (o.confirmTool && ready) {
        controller.reset();
        if (!controller.setSpindleToolNumber(*o.confirmTool)) {
            std::cerr << "m350-sim: "
                      << messageText("usage_confirm_refused", {"--confirm-tool " + std::to_string(*o.confirmTool)}, o.language)
                      << '\n';
            return kExitUsage;
        }
        report = controller.status().report();
    }
    std::optional<std::string> outputProblem = writeExternalOutput(controller, o);
    if (auto lifeProblem = saveToolLife(controller, config::MachineFolder(folder), o.language)) {
        outputProblem = lifeProblem;
    }
    printDiagnostics(report.diagnostics, o.language);
    if (report.alarm) {
        const Alarm& a = *report.alarm;
        // an alarm with no line (a native homing alarm names params.toml) is not placed at :0:0
        std::cerr << (a.file.empty() ? std::string("m350-sim") : a.file)
                  << (a.line > 0 ? ":" + std::to_string(a.line) + ":" + std::to_string(a.column) : std::string())
                  << ": " << messageText("stderr_alarm_tag", {}, o.language) << ": " // 报警 in Chinese, as 警告 for a warning
                  << (a.messageId.empty() ? a.message : messageText(a.messageId, a.messageArguments, o.language))
                  << '\n';
        if (a.callerLine > 0) {
            std::cerr << a.callerFile << ':' << a.callerLine << ": " << messageText("alarm_in_library_note", {}, o.language)
                      << '\n';
        }
    }
    printFallenTools(report.fallenTools, o.language);
    if (o.languageGiven) { // the run's notices, said in the language asked for (the JSON keeps the English)
        for (std::size_t i = 0; i < report.messages.size(); ++i) {
            const bool said = i < report.messageWords.size() && !report.messageWords[i].id.empty();
            std::cerr << "m350-sim: " << (o.language == MessageLanguage::Chinese ? "信息: " : "message: ")
                      << (said ? report.messageWords[i].in(o.language) : report.messages[i]) << '\n';
        }
    }
    if (auto error = sim::exportTools(controller, o)) {
        std::cerr << "m350-sim: --tools-out: " << error->in(o.language) << '\n';
        report.status = controller::RunStatus::Error;
    }
    nlohmann::json json = sim::reportJson(report, controller, o.printVariables);
    if (controller.toolLife().manager().enabled() || !lifeIssues.empty()) {
        json["tool_life"] = sim::toolLifeJson(controller.toolLife().manager(), lifeIssues);
    }
    if (controller.toolBreakage().spindleLoad().model()) {
        json["spindle_load"] = sim::spindleLoadJson(controller.toolBreakage().spindleLoad(), controller.dialect().id == gcode::DialectId::Fanuc);
    }
    if (trace) {
        controller.status().finishTrace();
        if (auto problem = trace->commit()) {
            std::cerr << "m350-sim: --trace: " << problem->in(o.language) << '\n';
            outputProblem = problem->english();
        }
    }
    if (outputProblem && json["alarm"].is_null()) { // what the run did was not all written: no success
        json["status"] = "error";
        json["alarm"] = sim::errorJson("file_error", *outputProblem, "")["alarm"];
    }
    std::cout << sim::dump(json) << '\n';
    if (outputProblem) {
        return kExitError;
    }
    switch (report.status) {
    case controller::RunStatus::Ok: return kExitOk;
    case controller::RunStatus::Alarm: return kExitAlarm;
    case controller::RunStatus::Error: return kExitError;
    }
    return kExitError;
}

} // namespace

int main(int argc, char** argv) {
    int status = kExitError;
    try {
        status = runCommand(argc, argv);
    } catch (const std::bad_alloc&) {
        // What the run held is freed by now, so there is room to say what happened.
        const char* message = "out of memory: the program (or what it made) did not fit in the memory "
                              "this process may use";
        std::cerr << "m350-sim: " << message << '\n';
        std::cout << sim::dump(sim::errorJson("out_of_memory", message, "")) << '\n';
    }
    return flushedStdout() ? status : kExitError;
}
