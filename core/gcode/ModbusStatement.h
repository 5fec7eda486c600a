#pragma once

#include "core/common/Message.h"

#include <cstdint>
#include <optional>
#include <string>

namespace m350::gcode {

// The M350's Modbus statements as the firmware takes them (its Russian Modbus manual, as owners
// who captured the frames on a PC slave document it: fchabot-dxf/ddcs-pc-bridge):
//   MSETDATA[X1, X2, X3, X4, X5, X6]   the bytes of #X1.. to the slave
//   MGETDATA[X1, X2, X3, X4, X5, X6]   the slave's bytes into #X1..
// X1 the first variable (#50-#499, one byte 0-255 each), X2 the slave, X3 the first register (or
// coil), X4 the length in bytes, X5 the Modbus function, X6 the variable that receives the
// exception code (0 = OK). X1 and X6 are variable numbers (200), not their values (#200).
// The parser checks the arguments written as numbers, the executor all of them, with these words.
struct ModbusStatement {
    enum Argument : int { FirstVariable, Slave, Address, Bytes, Function, ExceptionVariable, kCount };
    static constexpr int kFirstVariable = 50; // the statements' variables: #50-#499
    static constexpr int kLastVariable = 499;
    static constexpr double kTimeout = 16.0;  // s the controller waits for an answer

    bool write = false; // MSETDATA
    int firstVariable = 0;
    int slave = 0;
    int address = 0;
    int bytes = 0;
    int function = 0;
    int exceptionVariable = 0;

    static const char* name(bool write) { return write ? "MSETDATA" : "MGETDATA"; }
    // "MSETDATA[first variable, slave, register, bytes, function, exception variable]"
    static std::string usage(bool write);
    // What is wrong with `value` as argument `which` (0-5) of the statement, if anything
    // ("MSETDATA: the slave (X2) must be ...").
    static std::optional<Message> argumentProblem(bool write, int which, double value);
    // What is wrong with X4 bytes from #X1, if anything: they must end by #499.
    static std::optional<Message> spanProblem(bool write, int firstVariable, int bytes);
    // The Modbus functions each statement takes (what the firmware's documents show).
    static bool functionAllowed(bool write, int function);
    // "16 (write registers) or 15 (write coils)"
    static const char* functions(bool write);
};

} // namespace m350::gcode
