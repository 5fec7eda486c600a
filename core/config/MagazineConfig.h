#pragma once

#include <array>
#include <optional>
#include <vector>

namespace m350::config {

// The tool magazine of a machine folder, as the device beside the machine ([magazine] of
// machine.toml). Positions come from the parameters (M350) or from here (FANUC).
struct MagazineConfig {
    enum class Device { None, LinearRack, ServoDisc, Umbrella, MultiHead };
    Device device = Device::None;

    // linear-rack: pockets from params 830+/850+/870+; loading = "side" | "top", opening = "+Y" |
    // "-Y". A rack carried on the gantry (carried = "gantry", 龙门架直排) keeps its place in Y beside
    // the spindle; the magazine slide (output of param 753) pushes its forks out by slide_travel mm.
    bool topLoading = false;
    bool onGantry = false;
    double slideTravel = 100.0;
    double openingY = 1.0;
    double forkDepth = 30.0;
    double tolerance = 1.0;
    // Where the forks really stand (machine X Y Z, one a pocket): the iron, which params 830+ only
    // describe. Empty: where params 830+/850+/870+ say at power-on (a machine whose parameters are
    // right). A training exercise sets them so that a wrong parameter misses the fork.
    std::vector<std::array<double, 3>> forks;
    std::optional<std::array<double, 3>> station; // servo-disc: nose X Y Z with a tool seated at the station

    // multi-head (多工序, M350 type 1): param 801 heads (at most 4), lowered by the outputs of
    // params 777, 780, 783, 786; a head comes down only with Z at or above param 806.
    // servo-disc (圆盘, M350 type 4): the station is params 808/809 (X Y) and 807 (nose Z with a
    // tool seated), or where `station` says it stands (the iron, as forks above);
    // tool seated); pockets = param 801. The drive takes the pocket number in binary on
    // select_outputs (bit 0 first), starts on strobe_output and reports in_position_input.
    // umbrella (斗笠式, FANUC): pockets, change_xy (default: reference point 3), grip Z = reference
    // point 3, clear Z = reference point 2; slide_output with at_spindle_input and away_input;
    // in_position_input for the turn; the drawbar on drawbar_output with released_input and
    // clamped_input (on the M350 the drawbar and its sensors are params 750, 623, 626).
    int pockets = 0;
    double secondsPerPocket = 0.25;
    double settleSeconds = 0.1;
    std::vector<int> selectOutputs;
    int strobeOutput = 0;
    int inPositionInput = 0;
    double slideSeconds = 1.2;
    int slideOutput = 0;
    int atSpindleInput = 0;
    int awayInput = 0;
    bool changeXYGiven = false;
    double changeX = 0.0;
    double changeY = 0.0;
    int drawbarOutput = 0;
    int releasedInput = 0;
    int clampedInput = 0;
    // how long the clamp cylinder takes to reach either end; 0: param 814 when it is set (above its
    // default 1 ms), else 150 ms
    double clampSeconds = 0.0;

    bool present() const { return device != Device::None; }
};

} // namespace m350::config
