// FANUC's coordinate system rotation, G68 / G69 (an option of the 0i and the 30i: machine.toml
// [coordinates] rotation). `G17 G68 X_ Y_ R_` turns what the program says after it about the point
// X Y (absolute work coordinates; the tool's position for an axis left out) by R degrees,
// counter-clockwise seen from the plane's normal; G69 ends it. As FANUC's operator's manuals have it:
//   - an incremental command turns with the program: its move is the written one, turned;
//   - until an absolute command names an axis of the plane, the program turns about where the tool
//     stood at G68 (so a plane axis left out of that first absolute command reads from there);
//   - arcs turn whole: their end point and their I J K; R is a length and stays;
//   - reference returns (G27-G30) and changes of the coordinate system (G52-G59, G54.1, G92) must not
//     be given in G68 mode, nor another plane: here they are refused at the block;
//   - cutter compensation and tool length act on the turned path (they follow in ModalCompensation).
// The DRO and #5041-#5045 stay in the unturned work coordinates (FANUC's default display; Mach4's
// manual, which follows FANUC here, says the same), as do #5001-#5005.
#include "core/interp/ModalInterpreter.h"

#include "core/common/Numeric.h"

#include <array>
#include <cmath>
#include <optional>

namespace m350::interp {

using macro::WordValue;

namespace {

char letterOf(int axis) { return machine::kAxisNames[static_cast<std::size_t>(axis)]; }

std::string planeName(int u, int v) { return std::string(1, letterOf(u)) + " " + letterOf(v); }

} // namespace

void ModalInterpreter::startRotation(const Words& words, const WordValue& g68) {
    for (char c : {'I', 'J', 'K'}) {
        if (const WordValue* w = words.find(c)) {
            invalidWord(*w, message("word_g68_ijk", {wordText(*w)}));
        }
    }
    const PlaneAxes plane = planeAxes(state_.group(2));
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        const WordValue* w = words.find(letterOf(axis));
        if (w && axis != plane.u && axis != plane.v) {
            invalidWord(*w, message("word_g68_centre", {wordText(*w), planeName(plane.u, plane.v)}));
        }
    }
    if (compensating() && compensationPlane_.plane != plane.plane) {
        invalidWord(g68, message("word_g68_plane", {wordText(g68)}));
    }
    const machine::Axes work = basePosition() - workOffset();
    const WordValue* cu = words.find(letterOf(plane.u));
    const WordValue* cv = words.find(letterOf(plane.v));
    const std::array<double, 2> centre{cu ? cu->value * axisUnit(plane.u) : work(plane.u),
                                       cv ? cv->value * axisUnit(plane.v) : work(plane.v)};
    // R is absolute (FANUC parameter 5400 bit 0 RIN = 0, its default); without R parameter 5410,
    // whose default is 0
    const WordValue* angle = words.find('R');
    state_.rotation = PlaneRotation(plane.u, plane.v, centre, {work(plane.u), work(plane.v)}, angle ? angle->value : 0.0);
    state_.groups[16] = 68;
}

void ModalInterpreter::refuseUnderRotation(const Words& words) const {
    const bool rotatingBefore = state_.rotating() && !words.hasG(69);
    if (!rotatingBefore && !words.hasG(68)) {
        return;
    }
    for (const WordValue& g : words.g) {
        const int code = roundToInt(g.value);
        const bool whole = std::abs(g.value - code) < 1e-6;
        const char* why = nullptr;
        if (!whole && std::abs(g.value - 54.1) < 1e-6) {
            why = "word_g68_changes_system";
        } else if (whole && ((code >= 54 && code <= 59) || code == 52 || code == 92)) {
            why = "word_g68_changes_system";
        } else if (whole && code >= 27 && code <= 30) {
            why = "word_g68_reference_return";
        } else if (rotatingBefore && whole && code >= 17 && code <= 19 && code != state_.group(2)) {
            invalidWord(g, message("word_g68_plane_stays", {wordText(g)}));
        }
        if (why != nullptr) {
            invalidWord(g, message(why, {wordText(g)}));
        }
    }
}

machine::Axes ModalInterpreter::rotatedTarget(const Words& words) const {
    machine::Axes target = plainTarget(words, false);
    const machine::Axes turned = turnedInPlane(basePosition(), words);
    const PlaneRotation& r = state_.rotation;
    target(r.u()) = turned(r.u());
    target(r.v()) = turned(r.v());
    return target;
}

machine::Axes ModalInterpreter::turnedInPlane(const machine::Axes& from, const Words& words) const {
    const PlaneRotation& r = state_.rotation;
    auto inMillimetres = [&](int axis) -> std::optional<double> {
        const WordValue* w = words.find(letterOf(axis));
        return w ? std::optional<double>(w->value * axisUnit(axis)) : std::nullopt;
    };
    return r.turned(from, inMillimetres(r.u()), inMillimetres(r.v()), state_.incremental(), workOffset());
}

// From the first absolute command that names an axis of the plane on, the program turns about
// G68's centre.
void ModalInterpreter::noteAbsoluteCommand(const Words& words) {
    PlaneRotation& r = state_.rotation;
    if (r.absoluteSeen() || state_.incremental() || words.hasG(4) || words.hasG(10) || words.hasG(53) ||
        words.hasG(68)) {
        return;
    }
    if (words.find(letterOf(r.u())) || words.find(letterOf(r.v()))) {
        r.absoluteCommandSeen();
    }
}

} // namespace m350::interp
