#pragma once

#include "core/common/Message.h"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace m350::controller {
class Controller;
}

namespace m350::preview {

// A point of the machine view's scene, machine coordinates, mm.
struct ScenePoint {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
    friend bool operator==(const ScenePoint&, const ScenePoint&) = default;
};

struct SceneBox {
    ScenePoint low;
    ScenePoint high;
    friend bool operator==(const SceneBox&, const SceneBox&) = default;
};

// A tool as drawn: its length below the spindle nose and its diameter (the tool table's, else
// the Z offset for the length and the simulated world's tool for either); 0 when nobody knows.
struct SceneTool {
    int number = 0;
    double length = 0.0;
    double diameter = 0.0;
    friend bool operator==(const SceneTool&, const SceneTool&) = default;
};

// One pocket (a rack's fork, a disc's or carousel's cup, a multi-process head): where the spindle
// nose stands when the tool it holds sits in it, and the tool it holds now (0: empty).
struct ScenePocket {
    int number = 0;
    ScenePoint at;
    int tool = 0;
    bool atStation = false; // the disc's or carousel's pocket facing the spindle; a head that is down
    friend bool operator==(const ScenePocket&, const ScenePocket&) = default;
};

// The magazine as it stands at this moment: every pocket at its place (a carousel that turned or
// slid, a rack carried on the gantry, resolved to where they are now).
struct SceneMagazine {
    enum class Kind { None, LinearRack, ServoDisc, Umbrella, MultiHead };
    Kind kind = Kind::None;
    bool topLoading = false; // a rack loaded from above (no side opening)
    double openingY = 1.0;   // a side-loading rack's forks open toward +Y (1) or -Y (-1)
    bool onGantry = false;   // the rack travels in Y with the spindle (龙门架直排): its pockets' Y is where they are now
    // The pockets ride on the spindle's carriage (multi-process heads): each pocket's `at` is its
    // head's X Y offset from the spindle nose (params 890+/910+, Z 0), not a machine position; each
    // head holds its own tool (tool = head) and atStation marks a head its cylinder holds down.
    bool followsSpindle = false;
    std::vector<ScenePocket> pockets;
    // A disc or carousel: its centre and the radius its pockets stand on (radius 0: none).
    ScenePoint centre;
    double radius = 0.0;
    // The umbrella's slide: 0 away (retracted), 1 at the spindle; in between while it moves.
    double slide = 0.0;
    friend bool operator==(const SceneMagazine&, const SceneMagazine&) = default;
};

// A tool setter: the fixed setter (固定对刀, params 135/136 and the folder's setter top and
// radius), the floating block (浮动对刀) or a probe stylus; `top` is where it trips.
struct SceneSetter {
    enum class Kind { Fixed, Floating };
    Kind kind = Kind::Fixed;
    double x = 0.0;
    double y = 0.0;
    double top = 0.0;
    double radius = 0.0; // 0: no size known (the floating block lies wherever the tool comes down)
    friend bool operator==(const SceneSetter&, const SceneSetter&) = default;
};

// A Z level a tool change or setting uses (the rack's safe height, the pocket height, the
// setter's fast-approach height ...), drawn as a labelled line in the front view. The label is a
// message id, so the panel says it in its language.
struct SceneLevel {
    Message label;
    double z = 0.0;
    friend bool operator==(const SceneLevel& a, const SceneLevel& b) {
        return a.label.id == b.label.id && a.label.arguments == b.label.arguments && a.z == b.z;
    }
};

// A tool the spindle let go of with nothing under it: it lies on the table below where it fell.
struct SceneFallenTool {
    int tool = 0;
    ScenePoint at;
    friend bool operator==(const SceneFallenTool&, const SceneFallenTool&) = default;
};

// Everything of the machine the view draws besides the program's path and the moving spindle,
// built from the machine folder, the tool data and the simulated world at one moment. The
// spindle's position is not in it (the panel status has it every frame): the scene changes only
// when a tool, a pocket, the carousel or an offset does, so a snapshot shares it until then.
struct MachineScene {
    SceneBox travel;              // the soft-limit box (params 161-170), else the world's travel
    bool travelFromSoftLimits = false;
    SceneBox table;               // the machine table (top face at table.high.z)
    ScenePoint workZero;          // machine coordinates of the active work system's zero: where the
                                  // spindle tool's tip stands at work 0 (the nose at work 0 less its length)
    std::string workSystem;       // "G54", "G92", "G54.1 P3"
    int spindleTool = 0;          // 0: the spindle is empty
    std::map<int, SceneTool> tools; // every tool the view may draw, by number (spindle, pockets, fallen)
    SceneMagazine magazine;
    std::vector<SceneSetter> setters;
    std::vector<SceneLevel> levels;
    std::vector<SceneFallenTool> fallen;

    const SceneTool* tool(int number) const {
        auto it = tools.find(number);
        return it == tools.end() ? nullptr : &it->second;
    }
    friend bool operator==(const MachineScene&, const MachineScene&) = default;
};

// The scene of the machine `controller` drives, as it stands at its display time (a carousel's
// turn and slide; a gantry rack's Y at the spindle's display position).
MachineScene buildScene(const controller::Controller& controller);
// The scene now, shared: `last` itself when nothing in it changed, else a new object (what a
// panel publishes every frame, so a view redraws the machine only when it changed).
std::shared_ptr<const MachineScene> sceneSince(std::shared_ptr<const MachineScene> last,
                                               const controller::Controller& controller);

} // namespace m350::preview
