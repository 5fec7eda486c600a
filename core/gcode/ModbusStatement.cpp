#include "core/gcode/ModbusStatement.h"

#include <cmath>
#include <cstdio>

namespace m350::gcode {

namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", v);
    return text;
}

std::string range(const char* what, double low, double high, double v) {
    return std::string(what) + " must be a whole number from " + number(low) + " to " + number(high) + ", not " +
           number(v);
}

} // namespace

std::string ModbusStatement::usage(bool write) {
    return std::string(name(write)) + "[first variable, slave, register, bytes, function, exception variable]";
}

bool ModbusStatement::functionAllowed(bool write, int function) {
    return write ? function == 15 || function == 16 : function >= 1 && function <= 4;
}

const char* ModbusStatement::functions(bool write) {
    return write ? "16 (write registers) or 15 (write coils)"
                 : "3 (read holding registers), 4 (read input registers), 1 (read coils) or 2 (read discrete inputs)";
}

std::optional<std::string> ModbusStatement::argumentProblem(bool write, int which, double value) {
    const bool whole = std::abs(value - std::round(value)) < 1e-9;
    constexpr int kMaxBytes = kLastVariable - kFirstVariable + 1;
    switch (which) {
    case FirstVariable:
        if (!whole || value < kFirstVariable || value > kLastVariable) {
            return range("the first variable (X1)", kFirstVariable, kLastVariable, value) +
                   ": the Modbus statements move #50-#499, one byte each, and X1 is the number (200), not #200";
        }
        return std::nullopt;
    case Slave:
        return !whole || value < 1 || value > 247 ? std::optional(range("the slave (X2)", 1, 247, value))
                                                  : std::nullopt;
    case Address:
        return !whole || value < 0 || value > 65535 ? std::optional(range("the first register (X3)", 0, 65535, value))
                                                    : std::nullopt;
    case Bytes:
        return !whole || value < 1 || value > kMaxBytes
                   ? std::optional(range("the length (X4) counts bytes: it", 1, kMaxBytes, value))
                   : std::nullopt;
    case Function:
        if (!whole || !functionAllowed(write, static_cast<int>(std::lround(value)))) {
            return std::string("the Modbus function (X5) of ") + name(write) + " is " + functions(write) + ", not " +
                   number(value);
        }
        return std::nullopt;
    case ExceptionVariable:
        if (!whole || value < kFirstVariable || value > kLastVariable) {
            return range("the exception variable (X6)", kFirstVariable, kLastVariable, value) +
                   ": it receives the slave's exception code (0 = OK), and X6 is the number (300), not #300";
        }
        return std::nullopt;
    default: return std::nullopt;
    }
}

std::optional<std::string> ModbusStatement::spanProblem(int firstVariable, int bytes) {
    const int last = firstVariable + bytes - 1;
    if (last <= kLastVariable) {
        return std::nullopt;
    }
    return "X4 = " + std::to_string(bytes) + " bytes from #" + std::to_string(firstVariable) + " reach #" +
           std::to_string(last) + ": the Modbus statements' variables end at #" + std::to_string(kLastVariable);
}

} // namespace m350::gcode
