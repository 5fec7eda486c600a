#pragma once

#include "core/common/Alarm.h"
#include "core/params/ParameterTable.h"
#include "core/controller/ManualModes.h"
#include "core/machine/MachineTypes.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace m350::controller {

// Everything the panel shows of the controller at one moment, as plain values: the machine
// session copies it out of its worker thread and the widgets only ever read such a copy.
// Positions are where the axes are at the display time (inside a move, not at its end).
struct PanelStatus {
    enum class Run : std::uint8_t { Idle, Running, Hold, Finished, Alarm, EStop };
    Run run = Run::Idle;
    double time = 0.0; // the display's virtual time, s

    machine::Axes machine = machine::Axes::Zero(); // 机械坐标
    machine::Axes work = machine::Axes::Zero();    // 工件坐标
    std::array<bool, machine::kAxisCount> homed{}; // #1515-#1519
    // The axes the machine has (params::axisSetup: the drive assignment, params 488-492), their
    // names (params 443/444: the 4th and 5th are A, B or C) and which turn (449/450: degrees).
    std::array<bool, machine::kAxisCount> axisShown{true, true, true, false, false};
    std::array<char, machine::kAxisCount> axisName{'X', 'Y', 'Z', 'A', 'B'};
    std::array<bool, machine::kAxisCount> axisRotary{};
    int workSystem = 1; // #578: 0 = G92, 1..6 = G54..G59; FANUC: from 9 on G54.1 P1, P2 ...
    // Offsets in the variables' slot order: 0 G92, 1-6 G54-G59, 7 G52, 8 the common offset (公共偏置).
    std::array<machine::Axes, 9> workOffsets{};

    double feedOverride = 100.0;    // 进给倍率 FRO, %
    double spindleOverride = 100.0; // 主轴倍率 SRO, %
    double jogOverride = 100.0;     // 手动倍率 SJR, %
    JogMode jogMode = JogMode::Continuous; // 连续 CONT, 寸动 STEP, 手轮 MPG
    double jogStep = 0.1;           // mm (deg) per STEP press
    bool jogHighSpeed = false;      // 高速 / 低速
    bool jogging = false;           // a manual move is under way (a key held, a step, the wheel)
    bool guide = false;             // 试切: the handwheel guide is on
    int guideDirection = 0;         // +1 顺切 forward, -1 逆切 reverse, 0 at rest
    double guideOverride = 0.0;     // %, the rate the wheel gives the program now
    double feed = 0.0;              // programmed F, mm/min
    double spindleRpm = 0.0;        // speed of the turning spindle, with SRO applied
    machine::SpindleState spindle = machine::SpindleState::Stop; // 停止 正转 反转 点动 攻丝 准停
    int tool = 0;                   // 当前刀具: what the spindle holds
    std::optional<Alarm> toolUnsure; // a stop in a change left the tool in doubt (ToolDoubt::notice())
    int totalCount = 0;             // 总加工数 (param 201)
    int pieceCount = 0;             // 加工件数 (param 202)
    double runSeconds = 0.0;        // 加工时间 of the current run
    std::string modalLine;          // "G00 G17 G90 G94 G21 G40 G49 G80 G54 F3000 S12000"

    std::string message;            // the status line's #1503 text (empty when cleared)
    std::optional<Alarm> notice;    // the controller's warning that text is, by its message id (StatusBoard::warn)
    std::string programStop;        // why a run holds by itself (M00, G04 P-1), else empty
    std::optional<std::string> dialog; // the #1505 dialog the run waits on (Enter / Esc), if any
    std::optional<Alarm> alarm;
    // Where a crash alarm's move ran into the hardware (the end of that move: a pocket, the setter);
    // other alarms happen where the axes stand.
    std::optional<machine::Axes> alarmPlace;
    std::string file;               // file and line of the block being executed
    std::uint32_t line = 0;
    bool mdi = false;               // the loaded program is MDI lines
    std::uint64_t blocks = 0;
    std::uint64_t runMoves = 0;     // moves the run has made (the last one may be under way or coming)

    struct SensorWait {
        std::string input; // "IN11 (tool released)"
        int awaitedLevel = 1;
        double seconds = 0.0;
        std::string file;
        std::uint32_t line = 0;
    };
    std::optional<SensorWait> sensorWait;

    std::array<int, machine::kInputCount> inputs{};   // IN01-IN24 as the macros read them
    std::array<int, machine::kOutputCount> outputs{}; // OUT01-OUT21
    params::ParameterTable parameters; // as they stand now (tool Z offsets 930-945, setter 129-137, IO triples)
};

// The work system as the panel names it: "G92", "G54".."G59", "G54.1 P3".
inline std::string workSystemName(int slot) {
    if (slot >= 9) {
        return "G54.1 P" + std::to_string(slot - 8);
    }
    return slot == 0 ? std::string("G92") : "G" + std::to_string(53 + slot);
}

} // namespace m350::controller
