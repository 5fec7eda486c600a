#pragma once

#include "core/common/Message.h"
#include "core/devices/ModbusSlave.h"

#include <map>
#include <optional>
#include <string>

namespace m350::config {

// The Modbus RTU slaves on the M350's serial port, as the machine folder's modbus.toml states them
// at power-on: each slave address (1-247) with what it holds, by address 0-65535. A run reads and
// writes them in memory; the file is never written.
//
//   [slave.1.holding]      # holding registers of slave 1 (functions 3 and 16)
//   0 = 0                  # register address = value (0-65535, or -32768..-1 as two's complement)
//   10 = 16951             # = 66 << 8 | 55: MGETDATA reads #n = 55, #n+1 = 66
//   [slave.1.input]        # input registers (function 4)
//   [slave.1.coils]        # coils (functions 1 and 15): address = 0 or 1 (or false, true)
//   [slave.1.discrete]     # discrete inputs (function 2)
struct ModbusSlaves {
    std::map<int, devices::ModbusMemory> slaves;
};

// Reads modbus.toml; what is wrong with it (with its line), if anything. A missing file is no slave.
std::optional<Message> loadModbusSlaves(const std::string& path, ModbusSlaves& out);

} // namespace m350::config
