#pragma once

#include "core/controller/RunEvents.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace m350::training {

// A key the trainee pressed, with the attempt's time (the replay's `t`).
struct PressedKey {
    double t = 0.0;
    std::string name; // PanelKey's name: RESET, START ...
};

// What an attempt left and what happened in it, as the checks read it: collected once from the
// machine at the end (FactsFromController.h), so that grading is the same headless and in the panel.
struct AttemptFacts {
    int spindleTool = 0;
    std::map<int, int> pockets;                    // pocket -> tool (0: empty)
    std::map<int, double> parameters;              // the numbers the checks name
    std::map<int, std::optional<double>> variables; // nullopt: vacant
    std::map<int, double> toolOffsets;             // tool -> Z offset
    std::map<int, int> outputs;                    // OUTn -> level
    std::vector<controller::RunEvents::Event> events; // times counted from the attempt's start
    std::vector<PressedKey> keys;
    double timeUsed = 0.0;   // s from the start to the hand-in (or the last action)
    std::string machineFolder; // the attempt's machine folder as it ended (file_line checks read it)
};

} // namespace m350::training
