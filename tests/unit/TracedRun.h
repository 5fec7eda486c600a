#pragma once

// Runs a program with a trace and gives its machine events back as short texts, so a test can
// compare the exact sequence of moves: "rapid X5 Y0 Z10", "feed X5 Y0 Z-3 F100", "dwell 0.5",
// "spindle REV".

#include "RunProgram.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace m350::test {

// At most 4 decimals, no trailing zeros: 5, -2.746, 0.254.
inline std::string shortNumber(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4f", v);
    std::string text = buffer;
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') {
        text.pop_back();
    }
    return text == "-0" ? "0" : text;
}

struct TracedRun {
    ProgramRun run;
    std::vector<std::string> events;
    std::vector<std::string> signals; // "OUT03=1 at 0.601", "M83" (an M code the PMC answered)
};

inline TracedRun runTraced(config::MachineConfig config, const std::string& program,
                           controller::RunSettings settings = {}) {
    std::ostringstream trace;
    settings.trace = &trace;
    TracedRun traced{runProgram(std::move(config), program, std::move(settings)), {}, {}};
    std::istringstream in(trace.str());
    for (std::string line; std::getline(in, line);) {
        auto event = nlohmann::json::parse(line);
        std::string type = event["type"].get<std::string>();
        if (type == "move") {
            const auto& to = event["to"];
            std::string text = event["kind"].get<std::string>() + " X" + shortNumber(to["X"].get<double>()) +
                               " Y" + shortNumber(to["Y"].get<double>()) + " Z" +
                               shortNumber(to["Z"].get<double>());
            if (event["kind"] == "feed") {
                text += " F" + shortNumber(event["feed"].get<double>());
            }
            traced.events.push_back(text);
        } else if (type == "dwell") {
            traced.events.push_back("dwell " +
                                    shortNumber(event["end"].get<double>() - event["start"].get<double>()));
        } else if (type == "spindle") {
            traced.events.push_back("spindle " + event["state"].get<std::string>());
        } else if (type == "io") {
            traced.signals.push_back(event["port"].get<std::string>() + "=" + std::to_string(event["level"].get<int>()) +
                                     " at " + shortNumber(event["t"].get<double>()));
        } else if (type == "pmc") {
            traced.signals.push_back("M" + std::to_string(event["m"].get<int>()));
        }
    }
    return traced;
}

} // namespace m350::test
