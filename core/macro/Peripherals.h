#pragma once

#include "core/macro/MacroError.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace m350::macro {

// The devices beside the CNC that macro statements talk to: the external output device (FANUC
// POPEN, DPRNT, BPRNT, PCLOS) and Modbus RTU slaves (the M350's MSETDATA, MGETDATA). The
// controller implements it. Each call returns why the device refuses, which the executor raises as
// an alarm on the statement's line.
class Peripherals {
public:
    virtual ~Peripherals() = default;

    virtual std::optional<Message> openOutput() = 0;  // POPEN
    virtual std::optional<Message> closeOutput() = 0; // PCLOS
    // One DPRNT or BPRNT record as the device receives it, its end-of-block code included.
    virtual std::optional<Message> output(std::string_view statement, std::string_view record) = 0;

    // One MSETDATA or MGETDATA transfer: `bytes` bytes from or to the slave's registers (or coils)
    // from `address`, by Modbus `function`. A write carries the variables' bytes in `data`.
    struct ModbusRequest {
        bool write = false;
        int slave = 0;
        int function = 0;
        int address = 0;
        int bytes = 0;
        std::vector<std::uint8_t> data;
    };
    // The slave's answer: its exception code (0 = OK) and, for a read that succeeded, `bytes` bytes.
    struct ModbusAnswer {
        int exception = 0;
        std::vector<std::uint8_t> data;
    };
    // No answer yet: the controller waits for it (the virtual time has been let pass); the
    // statement runs again once the wait is over, and then has its answer or its alarm.
    struct ModbusPending {};
    // The answer, the wait, or the alarm when there is none (Modbus off, the slave silent).
    virtual std::variant<ModbusAnswer, ModbusPending, MacroError> modbus(const ModbusRequest& request) = 0;
};

} // namespace m350::macro
