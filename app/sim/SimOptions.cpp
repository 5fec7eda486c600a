#include "app/sim/SimOptions.h"
#include "app/sim/BreakageOptions.h"
#include "app/sim/ByteLimitOption.h"
#include "app/sim/UsageError.h"

#include "core/params/FanucParameters.h"
#include "core/config/HookFiles.h"
#include "core/params/ParameterCatalogue.h"
#include "core/params/ParameterLimits.h"

#include <CLI/CLI.hpp>

#include <charconv>
#include <map>
#include <cmath>
#include <iostream>
#include <stdexcept>

namespace m350::sim {

namespace {

double parseNumber(const std::string& text, const std::string& what) {
    double v = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || ptr != text.data() + text.size()) {
        throw UsageError(what, message("usage_not_number", {text}));
    }
    if (!std::isfinite(v)) {
        throw UsageError(what, message("usage_not_finite", {text}));
    }
    return v;
}

// CLI11's PositiveNumber lets "nan" through (nan <= 0 is false), which turned the runaway guard off.
const CLI::Validator positiveFinite(
    [](std::string& text) -> std::string {
        double v = 0;
        auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v) || v <= 0.0) {
            return "'" + text + "' is not a positive finite number of seconds";
        }
        return {};
    },
    "POSITIVE");

// `--config ""` silently ran the default machine: an empty name is no file or folder.
const CLI::Validator nonEmptyPath(
    [](std::string& text) -> std::string { return text.empty() ? "an empty name is no file or folder" : std::string(); },
    "PATH");

int parseWhole(const std::string& text, const std::string& what) {
    double v = parseNumber(text, what);
    if (!(v >= -1e9 && v <= 1e9) || v != std::trunc(v)) {
        throw UsageError(what, message("usage_not_whole", {text}));
    }
    return static_cast<int>(v);
}

std::pair<std::string, std::string> splitAssignment(const std::string& text, const std::string& what) {
    auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size()) {
        throw UsageError(what, message("usage_looks_like", {text, "N=V"}));
    }
    return {text.substr(0, eq), text.substr(eq + 1)};
}

// "IN11" (or "in11") -> 11, for the options that name an input.
int parseInputName(const std::string& name, const std::string& item, const std::string& what, const char* example) {
    if (name.size() < 3 || (name.rfind("IN", 0) != 0 && name.rfind("in", 0) != 0)) {
        throw UsageError(what, message("usage_looks_like", {item, example}));
    }
    int port = parseWhole(name.substr(2), what);
    if (port < 1 || port > 24) {
        throw UsageError(what, message("usage_inputs"));
    }
    return port;
}

// --fault IN12=delayed:0.05 | bouncing:0.02 | stuck:0: what the IO page's fault menu puts on.
machine::InputFault parseFault(const std::string& item) {
    auto [port, fault] = splitAssignment(item, "--fault");
    auto colon = fault.find(':');
    std::string kind = fault.substr(0, colon);
    if (colon == std::string::npos || colon + 1 == fault.size()) {
        throw UsageError("--fault", message("usage_looks_like", {item, bilingual("IN12=delayed:0.05 (delayed, bouncing or stuck)",
                                                                                    "IN12=delayed:0.05（delayed、bouncing或stuck）")}));
    }
    double value = parseNumber(fault.substr(colon + 1), "--fault");
    if (kind == "stuck") {
        if (value != 0.0 && value != 1.0) {
            throw UsageError("--fault", message("usage_stuck_level", {item}));
        }
        return machine::InputFault::stuck(static_cast<int>(value));
    }
    if (kind != "delayed" && kind != "bouncing") {
        throw UsageError("--fault", message("usage_no_fault", {kind, bilingual("delayed, bouncing or stuck",
                                                                              "delayed（延迟）、bouncing（抖动）或stuck（卡死）")}));
    }
    if (value <= 0.0) {
        throw UsageError("--fault", message("usage_fault_seconds", {item}));
    }
    return kind == "delayed" ? machine::InputFault::delayed(value) : machine::InputFault::bouncing(value);
}

// The --lang a command line asks for, read before CLI11 parses it: a usage error is said in it
// even when the option it refuses comes first (English when none or no valid one is given).
MessageLanguage languageAsked(int argc, char** argv) {
    MessageLanguage language = MessageLanguage::English;
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg(argv[i]);
        if (arg == "--lang" && i + 1 < argc) {
            parseMessageLanguage(argv[i + 1], language);
        } else if (arg.rfind("--lang=", 0) == 0) {
            parseMessageLanguage(arg.substr(7), language);
        }
    }
    return language;
}

} // namespace

ParseOutcome parseCommandLine(int argc, char** argv) {
    SimOptions o;
    CLI::App app{"m350-sim: runs M350 / FANUC macro programs on a simulated machine, headless"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("m350-sim ") + M350_VERSION + " (commit " + M350_COMMIT + ")");
    std::vector<std::string> params, vars, inputs, faults, breaks, loadLimits;
    std::string printList;
    bool unhomed = false;
    std::optional<int> tool;

    auto addMachineOptions = [&](CLI::App* cmd) {
        cmd->add_option("--config", o.configDir, "machine folder (default: the bundled M350 16-pocket linear rack)")
            ->check(nonEmptyPath);
        cmd->add_option("--dialect", o.dialect, "m350 or fanuc")->check(CLI::IsMember({"m350", "fanuc"}));
    };
    auto addLanguageOption = [&](CLI::App* cmd) {
        cmd->add_option_function<std::string>(
               "--lang",
               [&o](const std::string& name) {
                   parseMessageLanguage(name, o.language);
                   o.languageGiven = true;
               },
               "language of the alarm and finding lines on stderr: en (default) or zh_CN, as the panel says "
               "them; the JSON keeps its English message and gives the message_id")
            ->check(CLI::IsMember({"en", "zh_CN"}));
    };
    auto addRunOptions = [&](CLI::App* cmd) {
        addLanguageOption(cmd);
        addMachineOptions(cmd);
        cmd->add_option("--param", params, "set parameter N to V (N=V), repeatable");
        cmd->add_option("--var", vars, "set variable #N to V before the run (N=V), repeatable");
        cmd->add_option("--input", inputs, "hold input INnn at 0 or 1 for the whole run (IN11=0), repeatable");
        cmd->add_option("--fault", faults,
                        "a fault on input INnn for the whole run: IN12=delayed:SECONDS, bouncing:SECONDS or stuck:LEVEL, "
                        "repeatable");
        cmd->add_option("--break", breaks,
                        "tool N breaks in the simulated world, L mm shorter: T1=0.62 (before the run) or "
                        "T1=0.62@4.5 (at 4.5 s), repeatable");
        cmd->add_option("--load-limits", loadLimits,
                        "spindle load limits of tool N, lower:upper % (T1=8:60), over spindle-load.toml, repeatable");
        cmd->add_flag("--unhomed", unhomed, "start with no axis homed");
        cmd->add_flag("--home", o.home, "home (回零) every axis that has a home switch before the run");
        cmd->add_option("--tool", tool, "tool in the spindle at start");
        cmd->add_option("--print", printList, "variables to report, e.g. 1,100,1300");
        cmd->add_option("--trace", o.traceFile, "write JSON Lines events to FILE")->check(nonEmptyPath);
        addByteLimitOption(*cmd, "--trace-limit", o.settings.traceLimit, kMostTraceBytes,
                           "the most bytes the trace keeps (default 256M; K, M, G suffixes): past it the first lines "
                           "and the last ones, with a trace_truncated line between");
        cmd->add_option("--dprnt", o.outputFile,
                        "write what the program sends with POPEN/DPRNT/BPRNT/PCLOS to FILE (default: dprnt.txt "
                        "beside the program; for mdi and hook, in the current folder)")
            ->check(nonEmptyPath);
        addByteLimitOption(*cmd, "--dprnt-limit", o.settings.externalOutputLimit, kMostExternalOutputBytes,
                           "the most bytes of DPRNT output kept for --dprnt FILE (default 64M; K, M, G suffixes): "
                           "past it the first records and the last ones, with a line between");
        cmd->add_option("--tool-table", o.toolTableFile, "use this tool.tbl instead of the machine folder's")
            ->check(nonEmptyPath);
        cmd->add_option("--tools-out", o.toolsOut, "write the tool table as the run left it to FILE (tool.tbl format)")
            ->check(nonEmptyPath);
        cmd->add_option("--max-sim-time", o.settings.maxSimTime, "simulated seconds before a runaway stops")
            ->check(positiveFinite);
        cmd->add_flag("--single-block", o.settings.singleBlock,
                      "single block: hold after each block that reaches the machine, START pressed at once "
                      "(FANUC #3003 bit 0 suppresses it)");
        cmd->add_option("--pause-at", o.settings.pauseAt,
                        "press PAUSE (feed hold) when the run has gone S simulated seconds, START once the "
                        "machine stands (FANUC #3004 bit 0 holds it back)")
            ->check(positiveFinite);
        cmd->add_option("--estop-at", o.settings.estopAt,
                        "press 急停 (E-stop) when the run has gone S simulated seconds; stopped inside a tool "
                        "change, the report's tool_unsure says the controller no longer knows the spindle's tool")
            ->check(positiveFinite);
        cmd->add_option("--confirm-tool", o.confirmTool,
                        "after the run, press RESET and enter N as the tool the spindle holds (the panel's "
                        "设置目标刀具号), as the operator does after a stop in a change")
            ->check(CLI::NonNegativeNumber);
        cmd->add_option_function<std::string>(
               "--level",
               [&o](const std::string& name) {
                   const std::map<std::string, params::UserLevel> levels{{"guest", params::UserLevel::Guest},
                                                                         {"operator", params::UserLevel::Operator},
                                                                         {"admin", params::UserLevel::Admin},
                                                                         {"super", params::UserLevel::Super}};
                   o.settings.userLevel = levels.at(name);
               },
               "the panel's user level the MDI lines and the program run at: guest, operator, admin or super "
               "(default super); a parameter (#N+500) above it stops the run with rights_limited, as on the panel")
            ->check(CLI::IsMember({"guest", "operator", "admin", "super"}));
        cmd->add_option("--sensor-timeout", o.settings.sensorTimeout,
                        "simulated seconds a macro may wait for a sensor input before an alarm (default 10)")
            ->check(positiveFinite);
    };
    CLI::App* run = app.add_subcommand("run", "run a program to its end");
    run->add_option("PROGRAM", o.program, "program file (.nc)")->required();
    addRunOptions(run);
    CLI::App* mdi = app.add_subcommand("mdi", "run MDI lines in order, as the MDI screen does");
    mdi->add_option("LINES", o.mdiLines, "one or more lines")->required();
    addRunOptions(mdi);
    CLI::App* check = app.add_subcommand("check", "parse only and list every error");
    check->add_option("PROGRAM", o.program, "program file (.nc)")->required();
    addMachineOptions(check);
    addLanguageOption(check);
    check->add_flag("--lint", o.lint,
                    "also warn about what runs but is seldom meant: an input wait with no way out, a variable read "
                    "before it is set, an output left on, M30 right after M6");
    CLI::App* import = app.add_subcommand("import", "make a machine folder from a copy of an M350's system disk");
    import->add_option("BACKUP_DIR", o.backupDir, "the backup: the folder that holds setting, slib-g.nc ...")
        ->required()
        ->check(nonEmptyPath);
    import->add_option("--into", o.intoDir, "the new machine folder (missing or empty)")->required()->check(nonEmptyPath);
    import->add_option_function<std::string>(
              "--lang", [&o](const std::string& name) { parseMessageLanguage(name, o.language); },
              "language of what it prints on stderr: en (default) or zh_CN (the JSON stays English)")
        ->check(CLI::IsMember({"en", "zh_CN"}));
    CLI::App* hook = app.add_subcommand("hook", "run one of the machine folder's hook files as the panel would");
    hook->add_option("NAME", o.hookName, "fndzero, key-3, probe, T (#1504 = the target tool: --var 1504=5) ...")
        ->required()
        ->check(CLI::Validator(
            [](std::string& name) -> std::string {
                const config::HookFile* found = config::findHook(name);
                if (!found || !found->runnable) {
                    return "'" + name + "' is no hook file; the hooks are: " + config::runnableHookNames();
                }
                return {};
            },
            "HOOK"));
    addRunOptions(hook);
    CLI::App* toolsCmd = app.add_subcommand("tools", "list the machine's tool table (tool.tbl) as a run starts with it");
    addMachineOptions(toolsCmd);
    toolsCmd->add_option("--tool-table", o.toolTableFile, "read this tool.tbl instead of the machine folder's")
        ->check(nonEmptyPath);
    toolsCmd->add_flag("--tbl", o.toolsAsTable, "print the table in tool.tbl form instead of JSON");

    CLI::App* resetPasswords = app.add_subcommand(
        "reset-passwords", "write the machine folder's passwords.toml anew: every level opens with its default password "
                           "again (the repair of a passwords.toml the panel cannot trust)");
    resetPasswords->add_option("--config", o.configDir, "the machine folder")->required()->check(nonEmptyPath);
    resetPasswords->add_option_function<std::string>(
                      "--lang", [&o](const std::string& name) { parseMessageLanguage(name, o.language); },
                      "language of the line it prints: en (default) or zh_CN")
        ->check(CLI::IsMember({"en", "zh_CN"}));

    try {
        app.parse(argc, argv);
        o.command = run->parsed()      ? SimOptions::Command::Run
                    : mdi->parsed()    ? SimOptions::Command::Mdi
                    : import->parsed() ? SimOptions::Command::Import
                    : hook->parsed()   ? SimOptions::Command::Hook
                    : toolsCmd->parsed() ? SimOptions::Command::Tools
                    : resetPasswords->parsed() ? SimOptions::Command::ResetPasswords
                                       : SimOptions::Command::Check;
        for (const std::string& p : params) {
            auto [n, v] = splitAssignment(p, "--param");
            int number = parseWhole(n, "--param");
            if (number < 0 || number > params::kLastFanucParameter) {
                throw UsageError("--param", message("usage_param_range"));
            }
            double value = parseNumber(v, "--param");
            auto refused = params::isFanucParameterNumber(number) ? params::refusedFanucParameter(number, value)
                                                                 : params::refusedParameterValue(number, value);
            if (refused) {
                throw UsageError("--param", *refused);
            }
            if (auto unread = params::isFanucParameterNumber(number) ? params::unreadFanucParameter(number)
                                                                     : std::nullopt) {
                std::cerr << "m350-sim: "
                          << messageText("usage_warning", {"--param " + p, bilingual(*unread)}, languageAsked(argc, argv))
                          << '\n';
            }
            const auto* catalogue = std::get_if<params::ParameterCatalogue>(&params::ParameterCatalogue::bundled());
            if (catalogue && catalogue->find(number)) {
                if (auto problem = catalogue->validate(number, value)) {
                    std::cerr << "m350-sim: "
                              << messageText("param_kept_as_given", {"--param " + p, bilingual(*problem)}, languageAsked(argc, argv))
                              << '\n';
                }
            }
            o.settings.parameters[number] = value;
        }
        for (const std::string& p : vars) {
            auto [n, v] = splitAssignment(p, "--var");
            o.settings.variables[parseWhole(n, "--var")] = parseNumber(v, "--var");
        }
        for (const std::string& p : inputs) {
            auto [port, level] = splitAssignment(p, "--input");
            int k = parseInputName(port, p, "--input", "IN11=0");
            int l = parseWhole(level, "--input");
            if (l != 0 && l != 1) {
                throw UsageError("--input", message("usage_input_level"));
            }
            o.settings.heldInputs[k] = l;
        }
        for (const std::string& f : faults) {
            o.settings.inputFaults[parseInputName(splitAssignment(f, "--fault").first, f, "--fault", "IN12=delayed:0.05")] =
                parseFault(f);
        }
        for (const std::string& b : breaks) {
            o.settings.toolBreaks.push_back(parseToolBreak(b));
        }
        for (const std::string& l : loadLimits) {
            o.settings.loadLimits.insert_or_assign(parseLoadLimits(l).first, parseLoadLimits(l).second);
        }
        std::size_t start = 0;
        while (!printList.empty() && start <= printList.size()) {
            std::size_t comma = printList.find(',', start);
            std::string item = printList.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
            if (!item.empty() && item[0] == '#') {
                item.erase(0, 1);
            }
            o.printVariables.push_back(parseWhole(item, "--print"));
            if (comma == std::string::npos) {
                break;
            }
            start = comma + 1;
        }
        o.settings.homed = !unhomed;
        o.settings.tool = tool;
    } catch (const CLI::CallForHelp&) {
        std::cout << app.help();
        return {std::nullopt, 0};
    } catch (const CLI::CallForVersion& e) {
        std::cout << e.what() << '\n';
        return {std::nullopt, 0};
    } catch (const CLI::CallForAllHelp&) {
        std::cout << app.help("", CLI::AppFormatMode::All);
        return {std::nullopt, 0};
    } catch (const UsageError& e) {
        const MessageLanguage language = languageAsked(argc, argv);
        std::cerr << "m350-sim: " << e.text(language) << "\n" << messageText("usage_help", {}, language) << "\n";
        return {std::nullopt, 64};
    } catch (const CLI::ParseError& e) {
        std::cerr << "m350-sim: " << e.what() << "\n" << messageText("usage_help", {}, languageAsked(argc, argv)) << "\n";
        return {std::nullopt, 64};
    }
    return {o, 0};
}

} // namespace m350::sim
