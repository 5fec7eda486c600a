// `m350-sim hook NAME` and `--home`: the machine folder's hook files run as the panel runs them.
#include "app/sim/HookCommand.h"

#include "core/config/HookFiles.h"

namespace m350::sim {

namespace {

config::Hook hookOf(const SimOptions& o) { return config::findHook(o.hookName)->hook; } // checked when parsed

} // namespace

bool loadForCommand(controller::Controller& controller, const SimOptions& o) {
    switch (o.command) {
    case SimOptions::Command::Mdi: return controller.loadMdi(o.mdiLines);
    case SimOptions::Command::Hook: return controller.loadHook(hookOf(o));
    case SimOptions::Command::Run:
    case SimOptions::Command::Check:
    case SimOptions::Command::Import:
    case SimOptions::Command::Tools:
    case SimOptions::Command::ResetPasswords: break;
    }
    return controller.loadFile(o.program);
}

std::optional<Message> missingHook(const SimOptions& o, const config::MachineConfig& machine) {
    if (o.command != SimOptions::Command::Hook) {
        return std::nullopt;
    }
    const config::Hook hook = hookOf(o);
    if (config::hookPath(machine.folder, hook)) {
        return std::nullopt;
    }
    std::string present;
    for (const config::HookFile& file : config::hookFiles()) {
        if (file.runnable && config::hookPath(machine.folder, file.hook)) {
            present += present.empty() ? "" : ", ";
            present += file.name;
        }
    }
    return message("hook_missing_sim", {o.hookName, machine.folder, std::string(config::hookFile(hook).fileName),
                                        config::runsWhenWords(config::hookFile(hook)),
                                        present.empty() ? bilingual("none", "无") : present, config::runnableHookNames()});
}

std::optional<controller::RunReport> homeBeforeRun(controller::Controller& controller) {
    if (!controller.hasHook(config::Hook::HomeAll)) {
        if (controller.homing().home(controller.homing().homeableAxes())) {
            return controller.status().report();
        }
        return std::nullopt;
    }
    if (!controller.loadHook(config::Hook::HomeAll)) {
        controller::RunReport report = controller.status().report();
        report.status = controller::RunStatus::Error;
        return report;
    }
    controller::RunReport report = controller.run();
    if (report.status != controller::RunStatus::Ok) {
        return report;
    }
    return std::nullopt;
}

} // namespace m350::sim
