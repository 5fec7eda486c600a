#include "core/training/FactsFromController.h"

#include "core/controller/Controller.h"

namespace m350::training {

double attemptClock(const controller::Controller& controller) { return controller.displayTime(); }

AttemptFacts factsFromController(controller::Controller& controller, const Exercise& exercise, double attemptStart,
                                 const std::string& machineFolder) {
    AttemptFacts facts;
    const controller::RunReport report = controller.status().report();
    facts.spindleTool = report.tool;
    facts.pockets = report.pockets;
    for (const Check& check : exercise.checks) {
        switch (check.kind) {
        case Check::Kind::Parameter: facts.parameters[check.number] = controller.parameter(check.number); break;
        case Check::Kind::ToolOffset: facts.toolOffsets[check.number] = controller.toolData().z(check.number); break;
        case Check::Kind::Variable: {
            const macro::Value value = controller.variable(check.number);
            facts.variables[check.number] = value.vacant ? std::nullopt : std::optional<double>(value.number);
            break;
        }
        case Check::Kind::Output:
            if (check.number >= 1 && check.number <= static_cast<int>(report.outputs.size())) {
                facts.outputs[check.number] = report.outputs[static_cast<std::size_t>(check.number - 1)];
            }
            break;
        default: break;
        }
    }
    for (controller::RunEvents::Event event : controller.events().list()) {
        event.time -= attemptStart;
        facts.events.push_back(std::move(event));
    }
    facts.machineFolder = machineFolder;
    return facts;
}

} // namespace m350::training
