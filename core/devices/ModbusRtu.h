#pragma once

#include "core/common/Message.h"

#include <cstdint>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace m350::devices {

// Modbus RTU frames as the M350 (the master) sends MSETDATA and MGETDATA on its serial port, and
// reads the slave's answer. A frame is the slave address, the PDU (function code and data) and the
// CRC-16 (polynomial 0xA001, low byte first). The statements move bytes, one a variable: registers
// pack two of them, little-endian (register = second << 8 | first; an odd length leaves the last
// register's high byte 0 on a write and drops it on a read); coils take the bytes as they are,
// eight coils a byte, the first coil in the lowest bit (Modbus's own packing).
//   1 read coils            2 read discrete inputs   3 read holding registers
//   4 read input registers  15 write coils           16 write registers
namespace modbus {

using Frame = std::vector<std::uint8_t>;

std::uint16_t crc16(std::span<const std::uint8_t> bytes);
// The frame with its CRC appended.
Frame withCrc(Frame frame);
bool crcMatches(std::span<const std::uint8_t> frame);

bool isWrite(int function);
bool isCoilFunction(int function);
// How many registers or coils `bytes` bytes are (the request's quantity).
int quantity(int function, int bytes);

// The master's request: `bytes` bytes from `address` by `function`; a write carries them in `data`.
Frame request(int slave, int function, int address, int bytes, std::span<const std::uint8_t> data);

// What the slave answered to `sent`: its exception code (0 = OK) and, for a read that succeeded,
// the `bytes` bytes for the variables; or why the answer is not one to `sent` (by message id).
struct Reply {
    int exception = 0;
    std::vector<std::uint8_t> data;
};
std::variant<Reply, Message> readReply(std::span<const std::uint8_t> sent, int bytes,
                                           std::span<const std::uint8_t> answer);

// "01 10 00 00 00 02 04 16 0B 2C 21 .. .."
std::string hex(std::span<const std::uint8_t> frame);

} // namespace modbus

} // namespace m350::devices
