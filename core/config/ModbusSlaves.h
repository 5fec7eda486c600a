#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace m350::config {

// The Modbus RTU slaves on the M350's serial port, as the machine folder's modbus.toml states them
// at power-on: each slave address (1-247) with its holding registers (address 0-65535 -> 16-bit
// value). A run reads and writes them in memory; the file is never written.
//
//   [slave.1.holding]      # slave address 1
//   8192 = 0               # register address = value (0-65535, or -32768..-1 as two's complement)
//   8193 = 5000
struct ModbusSlaves {
    std::map<int, std::map<int, std::uint16_t>> holding;
};

// Reads modbus.toml; what is wrong with it (with its line), if anything. A missing file is no slave.
std::optional<std::string> loadModbusSlaves(const std::string& path, ModbusSlaves& out);

} // namespace m350::config
