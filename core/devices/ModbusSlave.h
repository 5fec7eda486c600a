#pragma once

#include "core/devices/ModbusRtu.h"

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <utility>

namespace m350::devices {

// What a Modbus slave holds, by address (0-65535): 16-bit holding and input registers, coils and
// discrete inputs. A table the slave does not have is empty.
struct ModbusMemory {
    std::map<int, std::uint16_t> holding;
    std::map<int, std::uint16_t> input;
    std::map<int, bool> coils;
    std::map<int, bool> discrete;
};

// A simulated Modbus RTU slave on the M350's serial line: it answers the frames addressed to it
// as the Modbus specification has a slave do, functions 1, 2, 3, 4, 15 and 16. Exception 01 for a
// function it has no table for (or does not know), 02 when an address asked for is not in its
// table (nothing is written then), 03 for a quantity beyond Modbus's limits (125 registers read,
// 123 written, 2000 coils read, 1968 written) or a byte count that does not match it.
class ModbusSlave {
public:
    ModbusSlave(int address, ModbusMemory memory) : address_(address), memory_(std::move(memory)) {}

    // The answer frame, or nothing: a frame for another slave, or one whose CRC is wrong, gets
    // none, as on the line.
    std::optional<modbus::Frame> answer(std::span<const std::uint8_t> request);
    const ModbusMemory& memory() const { return memory_; }

private:
    modbus::Frame exception(int function, int code) const;
    modbus::Frame read(int function, int start, int count);
    modbus::Frame write(int function, int start, int count, std::span<const std::uint8_t> data);

    int address_;
    ModbusMemory memory_;
};

} // namespace m350::devices
