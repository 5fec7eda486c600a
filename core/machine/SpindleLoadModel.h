#pragma once

#include <cstdint>
#include <limits>
#include <optional>

namespace m350::machine {

// The work on the table as the spindle load model sees it (machine.toml [stock]): a box whose top
// is a machine Z (tool tip) and whose X/Y extent is given or unbounded.
struct Stock {
    static constexpr double kUnbounded = std::numeric_limits<double>::infinity();
    double top = 0.0;
    double xMin = -kUnbounded, xMax = kUnbounded;
    double yMin = -kUnbounded, yMax = kUnbounded;
    bool covers(double x, double y) const { return x >= xMin && x <= xMax && y >= yMin && y <= yMax; }
};

// The simulated spindle motor (machine.toml [spindle_load]). The load in percent of rated output is
//   idle + perKrpm x rpm/1000                        while the spindle turns, plus
//   perCm3 x depth x width x feed / 1000            while the tool tip is below the stock's top
// (depth mm below the top, width = the tool's diameter in mm, feed mm/min: cm3/min removed).
// A tool that breaks spikes to spikeFactor x its cutting load for spikeSeconds, then cuts nothing.
struct SpindleLoadModel {
    static constexpr int kSignalMax = 32767; // the PMC window's full scale (function 153)
    double lambda = 143.0;                   // FANUC parameter 4127 (set by the controller): the load % at full scale
    double idle = 1.5;
    double perKrpm = 0.3;
    double perCm3 = 2.5;
    double spikeFactor = 2.5;
    double spikeSeconds = 0.3;
    double defaultWidth = 10.0; // mm, for a tool whose diameter the world does not say
    std::optional<Stock> stock;

    // The true load, % of rated output.
    double percent(double rpm, double feed, double depth, double width) const;
    // The signal L the PMC reads: load / lambda x 32767, rounded, kept in 0..32767.
    int signal(double percent) const;
};

// The article's conversion, Load% = L / 32767 x lambda.
double loadPercent(int signal, double lambda);
// What the PMC ladder stores for macros and the host: Load% x 100 (14300 x L / 32767 with
// lambda 143), truncated, in a 16-bit register.
std::uint16_t loadRegister(int signal, double lambda);

} // namespace m350::machine
