#pragma once

#include "core/interp/BlockWords.h"
#include "core/interp/DrillingCycle.h"

#include <cstdint>
#include <optional>

namespace m350::interp {

// FANUC's drilling data of the canned cycles (group 9): the drilling-axis word (Z under G17), R,
// Q and P as written, kept from block to block until G80, a group-1 code or the program end, and
// where the drilling axis stood when drilling began.
class DrillingData {
public:
    // What a cycle's data turn into machine positions by: mm per program unit and the work offset
    // of the drilling axis, the distance mode, G99, the peck clearance (mm) and what P counts.
    struct Frame {
        double unit = 1.0;
        double offset = 0.0;
        bool incremental = false;
        bool returnToR = false;
        double peckClearance = 0.0;
        double dwellScale = 1.0;
    };

    void clear() { *this = DrillingData{}; }
    // Takes the block's drilling words: the drilling axis's `drillLetter`, R, Q and P (not below 0).
    void remember(const BlockWords& words, char drillLetter);
    // How many holes the block drills: K, or L as LinuxCNC writes it (not both), 0-9999; 1 without.
    static int repeats(const BlockWords& words);
    // What a FANUC alarms on before the cycle moves for want of data: no bottom, no R, no Q for
    // G73/G83 (`column`: the cycle's G word).
    void checkComplete(const BlockWords& words, int code, char drillLetter, std::uint32_t column) const;
    // The drilling axis's machine position at the first hole of the cycle (kept until it ends).
    void startAt(double level) {
        if (!initialLevel_) {
            initialLevel_ = level;
        }
    }
    // The cycle G`code` drills with these data; alarms when the bottom is above R or a Q too small
    // makes pecks beyond count.
    DrillingCycle resolve(const BlockWords& words, int code, int drillAxis, const Frame& frame,
                          std::uint32_t column) const;

private:
    std::optional<double> bottom_;
    std::optional<double> r_;
    double q_ = 0.0;
    double p_ = 0.0;
    std::optional<double> initialLevel_;
};

} // namespace m350::interp
