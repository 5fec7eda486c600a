#pragma once

#include "core/params/ParameterNumbers.h"
#include "core/params/ParameterTable.h"
#include "core/common/Message.h"
#include "core/gcode/Dialect.h"
#include "core/interp/CutterCompensation.h"
#include "core/interp/DrillingData.h"
#include "core/interp/BlockWords.h"
#include "core/interp/ModalState.h"
#include "core/interp/OffsetsInForce.h"
#include "core/interp/WorkOffsets.h"
#include "core/machine/ArcGeometry.h"
#include "core/machine/MachineInterface.h"
#include "core/macro/BlockSink.h"
#include "core/tools/ToolData.h"

#include <array>
#include <bit>
#include <cstdint>
#include <functional>
#include <map>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace m350::interp {

// Turns evaluated blocks into machine commands, keeping the modal state.
//
// Order of execution within one block (written once, followed by execute()):
//   1. F, S, T, H, D words          5. work system (G54-G59, G54.1 Pn)
//   2. spindle M3/M4/M5/M19, M8/M9  6. non-modal G4, G28, G53, G92
//   3. plane, units, distance,      7. motion (G0 G1 G2 G3) with the axis words, or
//      feed mode, return level,        the active canned cycle (G73 G74 G81-G84) at them,
//      canned cycle; G69, then G68     turned by G68 (CoordinateRotation.cpp)
//      (its centre and angle)       8. M0, M1, M2, M30
//   4. cutter compensation (G40-G42), tool length (G43 G44 G49: the H offset is read here),
//      then G10 with the non-modal codes of 6, so `G43 H1 G10 L10 P1 Z0` applies tool 1's old
//      length and then changes the table, as LinuxCNC orders it (a second G43 applies the new one)
class ModalInterpreter : public macro::BlockSink {
public:
    // The coordinate functions FANUC sells as options, as the machine folder declares them
    // (machine.toml [coordinates]): G54.1 P1-P`additionalSystems`, G68/G69 when `rotation`.
    struct CoordinateFeatures {
        int additionalSystems = 0;
        bool rotation = false;
    };

    ModalInterpreter(const gcode::Dialect& dialect, params::ParameterTable& parameters, WorkOffsets& offsets,
                     tools::ToolData& tools, machine::MachineInterface& machine);
    // Its parts keep references to its members.
    ModalInterpreter(const ModalInterpreter&) = delete;
    ModalInterpreter& operator=(const ModalInterpreter&) = delete;

    // G30 P2/P3 (and G28 on FANUC, point 1) go to these machine positions; G28 on the M350 goes to
    // the position after homing (params 122-126).
    void setReferencePoint(int number, const machine::Axes& position) { referencePoints_[number] = position; }
    void setCoordinateFeatures(const CoordinateFeatures& features) { features_ = features; }

    macro::BlockOutcome execute(const macro::EvaluatedBlock& block) override;
    CycleContext cycleContext() const override;
    // Whether execute() acts on G`value` itself (not a macro call or a library's handler): what
    // `check` uses to say a G code is unknown without running.
    static bool knowsGCode(const gcode::Dialect& dialect, const CoordinateFeatures& features, double value);
    // Whether execute() takes M`code` (a FANUC's PMC takes every M code; an M350's firmware its own
    // few, the rest must have a handler in slib-m.nc), and what the alarm says when it does not.
    static bool knowsMCode(const gcode::Dialect& dialect, int code);
    // "M77: no such M code": `word` is the M word as written (M77).
    static Message unknownMCodeWords(const gcode::Dialect& dialect, int code, const std::string& word);

    const ModalState& state() const { return state_; }
    ModalState& state() { return state_; }
    // RESET selects G69, as it does on controls with G68 (the ISO modes of Yaskawa and Siemens say
    // so in as many words; a program's M02/M30 does it in execute()).
    void cancelRotation() { state_.groups[16] = 69; }

    // The active system's slot in WorkOffsets (1..6 for G54..G59, from 9 on G54.1 P1.., 0 for the
    // M350's G92 system).
    int activeSlot() const { return inForce_.activeSlot(); }
    // Total offset between machine and work coordinates for each axis, tool Z offset included
    // (OffsetsInForce: kept from block to block).
    const machine::Axes& workOffset() const { return inForce_.total(); }
    machine::Axes workPosition() const;
    // The Z offset of the tool in the spindle (M350: params 930-945, virtual tools 973-992).
    double toolZOffset() const { return inForce_.toolZOffset(); }
    int currentTool() const { return inForce_.currentTool(); }
    // FANUC G43/G44 H: + or - the length of offset H as G43/G44 (or the last H under them) read it;
    // 0 under G49. A later change of the offset applies from the next G43/G44 or H word.
    double toolLengthOffset() const { return inForce_.toolLengthOffset(); }
    // What touch off does after writing the tool's length: G43 H`number`, reading it now.
    void applyLengthOffset(int number);
    // mm per program unit for an axis: 25.4 under G20 for X Y Z and for a linear 4th/5th axis
    // (params 449/450 = 0); rotary axes (degrees) and G21 values are as written.
    double axisUnit(int axis) const;

    // The last G31: whether the signal came, where (machine coordinates), which axes moved.
    struct Probe {
        bool triggered = false;
        machine::Axes position = machine::Axes::Zero();
        std::uint32_t axes = 0; // bit per axis commanded in the G31 block
        // M350 #1920-#1924: 2 where the signal came on a commanded axis, else 0; a macro may write
        // them (probing macros clear them to 0 before the next probe)
        std::array<double, machine::kAxisCount> status{};
    };
    const Probe& lastProbe() const { return probe_; }
    // Which axes are homed (#1515-#1519, 1 homed, kept by the controller); without them every axis
    // counts as homed. The soft limits guard only homed axes.
    void setHomedFlags(const std::array<int, machine::kAxisCount>* homed) { homed_ = homed; }
    void setProbeStatus(int axis, double value) { probe_.status[static_cast<std::size_t>(axis)] = value; }

    // A stop for the operator met by the last block: the run waits for START (循环启动) there.
    struct OperatorStop {
        enum class Kind { Program, Optional, WaitForStart } kind = Kind::Program; // M00, M01, G04 P-1
        std::string what;                  // "M00 program stop"
        gcode::SourceLocation location;    // the block that stopped
    };
    std::optional<OperatorStop> takeStop() {
        if (!stop_) [[likely]] {
            return std::nullopt; // asked after every block: most leave none
        }
        return takeMadeStop();
    }

    // The look-ahead and contour-control modes the last blocks switched (FANUC `G05.1 Q1`, `G08 P0`,
    // `G05 P10000`), as written, for the trace; they change no geometry (LookAheadCodes.cpp).
    bool hasLookAheadChanges() const { return !lookAheadChanges_.empty(); }
    std::vector<std::string> takeLookAheadChanges();

    // A FANUC M06 the interpreter ran itself (no program is mapped to it): the tool T selected is
    // the spindle's now, as far as the control knows; `byHand` for LinuxCNC's M61 Qn, which sets
    // the number without a change (no pockets move). The controller takes it after each block.
    struct ToolChange {
        int tool = 0;
        bool byHand = false;
    };
    std::optional<ToolChange> takeToolChange() { return std::exchange(toolChange_, std::nullopt); }
    // The tool the spindle holds, as the controller knows it (G10 L0 is refused with one loaded).
    void setSpindleToolSource(std::function<int()> source) { spindleTool_ = std::move(source); }
    // Lines of tool.tbl the last G10 L0 skipped, for the controller to tell.
    bool hasReloadIssues() const { return !reloadIssues_.empty(); }
    std::vector<std::string> takeReloadIssues() { return std::exchange(reloadIssues_, {}); }

private:
    using Words = BlockWords;

    void applyGCodes(const Words& words);
    bool lookAheadCode(const macro::WordValue& g, const Words& words);
    static bool isLookAheadBlock(const Words& words);
    static bool isLookAheadCode(double value);
    // The G codes that make a block other than a plain move, as bits the way Words keeps them.
    static constexpr std::array<std::uint64_t, 2> kNotAPlainMove{
        (std::uint64_t{1} << 4) | (std::uint64_t{1} << 10) | (std::uint64_t{1} << 28) | (std::uint64_t{1} << 30) |
            (std::uint64_t{1} << 31) | (std::uint64_t{1} << 52) | (std::uint64_t{1} << 53),
        (std::uint64_t{1} << (68 - 64)) | (std::uint64_t{1} << (92 - 64))}; // G4 G10 G28 G30 G31 G52 G53; G68 G92
    void moveAxes(const Words& words) {
        // Most blocks are a plain move (G1 X.. Y..): none of those codes, no canned cycle
        if (!words.hasAnyG(kNotAPlainMove) && state_.group(9) == 80 &&
            !(dialect_.lookAheadCodes && isLookAheadBlock(words))) {
            if (words.hasAxis()) {
                moveTo(targetFor(words, false), words);
            }
            return;
        }
        moveOtherwise(words);
    }
    void moveOtherwise(const Words& words); // the rest of moveAxes
    machine::Axes targetFor(const Words& words, bool machineCoordinates) const {
        if (state_.rotating() && !machineCoordinates) [[unlikely]] {
            return rotatedTarget(words);
        }
        return plainTarget(words, machineCoordinates);
    }
    machine::Axes plainTarget(const Words& words, bool machineCoordinates) const;
    // G68 (CoordinateRotation.cpp): the block's target with the plane's axes turned; `from` (machine
    // coordinates) with the plane's words, as the program turned counts them, applied.
    machine::Axes rotatedTarget(const Words& words) const;
    machine::Axes turnedInPlane(const machine::Axes& from, const Words& words) const;
    void startRotation(const Words& words, const macro::WordValue& g68);
    void refuseUnderRotation(const Words& words) const;
    void noteAbsoluteCommand(const Words& words);
    void selectAdditionalSystem(const Words& words, const macro::WordValue& g);
    void setCoordinateSystem(const Words& words); // G92, G52
    void setOffsets(const Words& words);          // G10
    void setToolOffsets(const Words& words, const macro::WordValue& g10, int kind); // G10 L1, L10-L13
    void reloadToolTable(const macro::WordValue& g10);                               // G10 L0
    void setDynamicLength(const macro::WordValue& g, const Words& words);             // G43.1
    void setToolNumber(const macro::WordValue& m, const Words& words);                // M61
    void needLinuxCncTable(const macro::WordValue& w, const std::string& what) const;
    void setOffsetRegister(const Words& words, int kind);                             // FANUC's P R
    void setToolTable(const Words& words, const macro::WordValue& g10, int kind); // LinuxCNC's, axis words
    void latchLengthOffset(const Words& words);
    void goToReference(const Words& words, int point);
    void probeMove(const Words& words);
    void switchFunctionOutput(int outputTriple, bool on, std::optional<int> responseParameter);
    void moveTo(const machine::Axes& target, const Words& words);
    // Asked before every move: the limits are looked at only when param 155 switches them on.
    void checkSoftLimits(const machine::Axes& target, const Words& words) const {
        if (parameters_.get(param::kSoftLimitsEnabled) != 0.0) {
            checkAgainstSoftLimits(target, words);
        }
    }
    void checkAgainstSoftLimits(const machine::Axes& target, const Words& words) const;
    std::uint32_t motionColumn(const Words& words) const;
    double feedRate(std::uint32_t column) const; // mm/min, from F and (G95) the spindle speed
    // The feed of the block's move; its column (for G95's alarm) is looked for only under G95.
    double motionFeedRate(const Words& words) const {
        return state_.group(5) != 95 || dialect_.id == gcode::DialectId::M350 ? state_.feed
                                                                               : feedRate(motionColumn(words));
    }
    void stopForOperator(OperatorStop::Kind kind, std::string what);
    std::optional<OperatorStop> takeMadeStop();
    bool compensating() const { // asked for every move
        return compensation_.side() != CompensationSide::Off || compensation_.hasPending();
    }
    // The compensation plane's axes (u, v), u x v along its normal.
    struct PlaneAxes {
        int u = 0;
        int v = 1;
        machine::Plane plane = machine::Plane::XY;
    };
    static PlaneAxes planeAxes(int planeCode);
    Eigen::Vector2d inPlane(const machine::Axes& p) const;
    machine::Axes basePosition() const { return compensating() ? programmed_ : machine_.position(); }
    double compensationRadius() const;
    void compensatedMove(const machine::Axes& target, const Words& words);
    void emitToolPath(const std::vector<PathSegment>& segments);
    void flushCompensation();
    void cancelCycle() { // every plain move ends any cycle
        state_.groups[9] = 80;
        drilling_.clear();
    }
    void cannedCycle(const Words& words);
    void checkCycle(const Words& words, int code, char drillLetter) const;
    std::vector<machine::Axes> cycleHoles(const Words& words, int repeats) const;
    void runCycle(const DrillingCycle& cycle, const std::vector<machine::Axes>& holes, const Words& words);
    std::uint32_t cycleColumn(const Words& words) const;

    const gcode::Dialect& dialect_;
    CoordinateFeatures features_;
    params::ParameterTable& parameters_;
    WorkOffsets& offsets_;
    tools::ToolData& tools_;
    machine::MachineInterface& machine_;
    ModalState state_;
    Words words_;
    OffsetsInForce inForce_{dialect_, parameters_, offsets_, state_}; // after state_, which it reads
    std::optional<OperatorStop> stop_;
    std::vector<std::string> lookAheadChanges_;
    std::optional<ToolChange> toolChange_;
    std::function<int()> spindleTool_;
    std::vector<std::string> reloadIssues_;
    bool dynamicLength_ = false; // the block is G43.1: its axis words are offsets, nothing moves
    const gcode::Block* block_ = nullptr; // the block being executed
    std::map<int, machine::Axes> referencePoints_;
    CutterCompensation compensation_;
    Probe probe_;
    const std::array<int, machine::kAxisCount>* homed_ = nullptr;
    machine::Axes programmed_ = machine::Axes::Zero();    // where the program is, ahead of the machine
    machine::Axes pendingHeight_ = machine::Axes::Zero(); // Z, A, B of the move being compensated
    int pendingMode_ = 1;                                  // its motion mode (0 rapid, 1 feed)
    PlaneAxes compensationPlane_;                          // fixed from G41/G42 entry to G40 exit

    DrillingData drilling_; // the canned cycles' data, from block to block
};

} // namespace m350::interp
