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

std::optional<Message> ModbusStatement::argumentProblem(bool write, int which, double value) {
    const bool whole = std::abs(value - std::round(value)) < 1e-9;
    constexpr int kMaxBytes = kLastVariable - kFirstVariable + 1;
    const std::string statement = name(write);
    switch (which) {
    case FirstVariable:
        if (!whole || value < kFirstVariable || value > kLastVariable) {
            return message("modbus_first_variable",
                           {statement, number(kFirstVariable), number(kLastVariable), number(value)});
        }
        return std::nullopt;
    case Slave:
        return !whole || value < 1 || value > 247 ? std::optional(message("modbus_slave", {statement, number(value)}))
                                                  : std::nullopt;
    case Address:
        return !whole || value < 0 || value > 65535
                   ? std::optional(message("modbus_register", {statement, number(value)}))
                   : std::nullopt;
    case Bytes:
        return !whole || value < 1 || value > kMaxBytes
                   ? std::optional(message("modbus_bytes", {statement, number(kMaxBytes), number(value)}))
                   : std::nullopt;
    case Function:
        if (!whole || !functionAllowed(write, static_cast<int>(std::lround(value)))) {
            return message(write ? "modbus_function_write" : "modbus_function_read", {statement, number(value)});
        }
        return std::nullopt;
    case ExceptionVariable:
        if (!whole || value < kFirstVariable || value > kLastVariable) {
            return message("modbus_exception_variable",
                           {statement, number(kFirstVariable), number(kLastVariable), number(value)});
        }
        return std::nullopt;
    default: return std::nullopt;
    }
}

std::optional<Message> ModbusStatement::spanProblem(bool write, int firstVariable, int bytes) {
    const int last = firstVariable + bytes - 1;
    if (last <= kLastVariable) {
        return std::nullopt;
    }
    return message("modbus_span", {name(write), std::to_string(bytes), std::to_string(firstVariable),
                                   std::to_string(last), std::to_string(kLastVariable)});
}

} // namespace m350::gcode
