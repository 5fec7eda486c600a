#pragma once

#include "core/common/Alarm.h"
#include "core/common/HeadTail.h"
#include "core/machine/MachineTypes.h"

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

namespace m350::controller {

// Where an event came from in the program.
struct TraceSource {
    std::string file;
    std::uint32_t line = 0;
};

// Writes one JSON object per line (JSON Lines) for each event, with its virtual time and the
// source line that caused it: move, io, spindle, coolant, dwell, toolchange, message, alarm.
// At most `limit` bytes are written: the lines go out as they come until the limit less the tail
// budget (a quarter of the limit, at most 16 MiB) is reached; after that only the newest lines are
// kept, and finish() writes a `trace_truncated` line (how many lines and bytes were left out) and
// then those last lines.
class TraceWriter {
public:
    TraceWriter(std::ostream& out, std::uint64_t limit);
    // Writes the kept last lines after the note about the left-out ones (once; nothing when the
    // trace stayed under its limit).
    void finish();

    void machineEvent(const machine::MachineEvent& event, const TraceSource& source);
    void message(double time, std::string_view text, const TraceSource& source);
    void toolChange(double time, int from, int to, const TraceSource& source);
    void alarm(double time, const Alarm& alarm);
    // A change of the run state the operator caused: pause, resume, reset, estop.
    void runState(double time, std::string_view state);
    // A pause the program asked for (M00, M01, G04 P-1): why, and the block that asked.
    void programStop(double time, std::string_view reason, const TraceSource& source);
    // A look-ahead or contour-control mode switched (`G05.1 Q1`): recorded, it moves nothing.
    void lookAhead(double time, std::string_view code, const TraceSource& source);
    // The external output device: POPEN and PCLOS (no record), a DPRNT record (as text) or a BPRNT
    // record (as hexadecimal bytes).
    void externalOutput(double time, std::string_view statement, std::string_view record, const TraceSource& source);
    // An MSETDATA or MGETDATA transfer: the request frame and the slave's answer (hex), none when
    // the slave was silent; the exception code when the answer is a Modbus frame (0 = OK).
    struct ModbusTransfer {
        std::string statement;
        int slave = 0;
        int function = 0;
        int address = 0;
        int bytes = 0;
        std::string request;
        std::optional<std::string> answer;
        std::optional<int> exception;
    };
    void modbus(double time, const ModbusTransfer& transfer, const TraceSource& source);
    // A macro began waiting for an input to reach `level` (the sensor watchdog's first notice).
    void sensorWait(double time, std::string_view port, int level, const TraceSource& source);

private:
    void writeLine(std::string line);

    std::ostream& out_;
    std::uint64_t limit_;
    HeadTail<std::string> kept_;
    bool finished_ = false;
};

} // namespace m350::controller
