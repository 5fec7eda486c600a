#include "core/devices/ModbusSlave.h"

namespace m350::devices {

namespace {

constexpr int kIllegalFunction = 1;
constexpr int kIllegalAddress = 2;
constexpr int kIllegalValue = 3;

int get16(std::span<const std::uint8_t> bytes, std::size_t at) {
    return bytes[at] << 8 | bytes[at + 1];
}

void put16(modbus::Frame& frame, int value) {
    frame.push_back(static_cast<std::uint8_t>((value >> 8) & 0xFF));
    frame.push_back(static_cast<std::uint8_t>(value & 0xFF));
}

template <typename Table> bool holdsAll(const Table& table, int start, int count) {
    for (int a = start; a < start + count; ++a) {
        if (table.count(a) == 0) {
            return false;
        }
    }
    return true;
}

} // namespace

std::optional<modbus::Frame> ModbusSlave::answer(std::span<const std::uint8_t> request) {
    if (request.size() < 4 || !modbus::crcMatches(request) || request[0] != address_) {
        return std::nullopt;
    }
    const std::span<const std::uint8_t> pdu = request.subspan(1, request.size() - 3);
    const int function = pdu[0];
    switch (function) {
    case 1: case 2: case 3: case 4:
        return pdu.size() == 5 ? read(function, get16(pdu, 1), get16(pdu, 3)) : exception(function, kIllegalValue);
    case 15: case 16:
        if (pdu.size() < 6 || pdu.size() - 6 != pdu[5]) {
            return exception(function, kIllegalValue);
        }
        return write(function, get16(pdu, 1), get16(pdu, 3), pdu.subspan(6));
    default: return exception(function, kIllegalFunction);
    }
}

modbus::Frame ModbusSlave::exception(int function, int code) const {
    return modbus::withCrc({static_cast<std::uint8_t>(address_), static_cast<std::uint8_t>(function | 0x80),
                            static_cast<std::uint8_t>(code)});
}

modbus::Frame ModbusSlave::read(int function, int start, int count) {
    const bool bits = function == 1 || function == 2;
    if (count < 1 || count > (bits ? 2000 : 125)) {
        return exception(function, kIllegalValue);
    }
    const auto& registers = function == 3 ? memory_.holding : memory_.input;
    const auto& flags = function == 1 ? memory_.coils : memory_.discrete;
    if (bits ? flags.empty() : registers.empty()) {
        return exception(function, kIllegalFunction);
    }
    if (start + count > 65536 || !(bits ? holdsAll(flags, start, count) : holdsAll(registers, start, count))) {
        return exception(function, kIllegalAddress);
    }
    modbus::Frame frame{static_cast<std::uint8_t>(address_), static_cast<std::uint8_t>(function)};
    if (bits) {
        frame.push_back(static_cast<std::uint8_t>((count + 7) / 8));
        for (int i = 0; i < count; ++i) {
            if (i % 8 == 0) {
                frame.push_back(0);
            }
            if (flags.at(start + i)) {
                frame.back() = static_cast<std::uint8_t>(frame.back() | 1 << (i % 8));
            }
        }
    } else {
        frame.push_back(static_cast<std::uint8_t>(2 * count));
        for (int a = start; a < start + count; ++a) {
            put16(frame, registers.at(a));
        }
    }
    return modbus::withCrc(std::move(frame));
}

modbus::Frame ModbusSlave::write(int function, int start, int count, std::span<const std::uint8_t> data) {
    const bool bits = function == 15;
    const int limit = bits ? 1968 : 123;
    const int byteCount = bits ? (count + 7) / 8 : 2 * count;
    if (count < 1 || count > limit || static_cast<int>(data.size()) != byteCount) {
        return exception(function, kIllegalValue);
    }
    if (bits ? memory_.coils.empty() : memory_.holding.empty()) {
        return exception(function, kIllegalFunction);
    }
    if (start + count > 65536 ||
        !(bits ? holdsAll(memory_.coils, start, count) : holdsAll(memory_.holding, start, count))) {
        return exception(function, kIllegalAddress);
    }
    for (int i = 0; i < count; ++i) {
        if (bits) {
            memory_.coils[start + i] = (data[static_cast<std::size_t>(i / 8)] >> (i % 8) & 1) != 0;
        } else {
            memory_.holding[start + i] = static_cast<std::uint16_t>(get16(data, 2 * static_cast<std::size_t>(i)));
        }
    }
    modbus::Frame frame{static_cast<std::uint8_t>(address_), static_cast<std::uint8_t>(function)};
    put16(frame, start);
    put16(frame, count);
    return modbus::withCrc(std::move(frame));
}

} // namespace m350::devices
