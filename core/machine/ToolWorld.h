#pragma once

#include <functional>
#include <optional>
#include <vector>

namespace m350::machine {

// A tool that breaks in the simulated world: from virtual time `at` on it is `shortBy` mm shorter
// than it was (`m350-sim --break T1=0.62@4`), and it cuts no more.
struct ToolBreak {
    int tool = 0;
    double shortBy = 0.0;
    double at = 0.0;
};

// The tools as they really are (machine.toml [tools] length / diameter, T1 first), which no
// parameter or tool table says: where a setter trips, how wide a cut is, and which tools broke.
class ToolWorld {
public:
    ToolWorld() = default;
    ToolWorld(std::vector<double> lengths, std::vector<double> diameters)
        : lengths_(std::move(lengths)), diameters_(std::move(diameters)) {}

    void addBreak(const ToolBreak& broken) { breaks_.push_back(broken); }
    const std::vector<ToolBreak>& breaks() const { return breaks_; }

    // A tool the world does not list (a virtual tool the operator puts in by hand) is as long as
    // `length` says; without it, 0.
    void setUnlisted(std::function<double(int)> length) { unlisted_ = std::move(length); }
    // The length as made.
    double nominalLength(int tool) const {
        const std::optional<double> listed = entry(lengths_, tool);
        return listed ? *listed : unlisted_ ? unlisted_(tool) : 0.0;
    }
    // The length at virtual time t: the nominal one less every break due by then.
    double length(int tool, double t) const;
    // The diameter, when the world says it (a setter's side contact and the width of a cut need it).
    std::optional<double> diameter(int tool) const { return entry(diameters_, tool); }
    // Whether the tool has broken by virtual time t.
    bool broken(int tool, double t) const;
    // The earliest break of the tool, if it breaks at all.
    std::optional<double> breakTime(int tool) const;

private:
    static std::optional<double> entry(const std::vector<double>& values, int tool);
    std::vector<double> lengths_;
    std::vector<double> diameters_;
    std::vector<ToolBreak> breaks_;
    std::function<double(int)> unlisted_;
};

} // namespace m350::machine
