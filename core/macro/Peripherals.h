#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace m350::macro {

// The devices beside the CNC that macro statements talk to: the external output device (FANUC
// POPEN, DPRNT, BPRNT, PCLOS) and Modbus RTU slaves (the M350's MSETDATA, MGETDATA). The
// controller implements it. Each call returns why the device refuses, which the executor raises as
// an alarm on the statement's line.
class Peripherals {
public:
    virtual ~Peripherals() = default;

    virtual std::optional<std::string> openOutput() = 0;  // POPEN
    virtual std::optional<std::string> closeOutput() = 0; // PCLOS
    // One DPRNT or BPRNT record as the device receives it, its end-of-block code included.
    virtual std::optional<std::string> output(std::string_view statement, std::string_view record) = 0;

    // A holding register of a slave (Modbus function 06 and 03).
    virtual std::optional<std::string> writeRegister(int slave, int address, std::uint16_t value) = 0;
    virtual std::variant<std::uint16_t, std::string> readRegister(int slave, int address) = 0;
};

} // namespace m350::macro
