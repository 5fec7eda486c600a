#include "core/devices/ModbusRtu.h"

namespace m350::devices::modbus {

namespace {

void put16(Frame& frame, int value) {
    frame.push_back(static_cast<std::uint8_t>((value >> 8) & 0xFF));
    frame.push_back(static_cast<std::uint8_t>(value & 0xFF));
}

int get16(std::span<const std::uint8_t> frame, std::size_t at) {
    return frame[at] << 8 | frame[at + 1];
}

} // namespace

std::uint16_t crc16(std::span<const std::uint8_t> bytes) {
    std::uint16_t crc = 0xFFFF;
    for (std::uint8_t byte : bytes) {
        crc ^= byte;
        for (int bit = 0; bit < 8; ++bit) {
            crc = (crc & 1) != 0 ? static_cast<std::uint16_t>((crc >> 1) ^ 0xA001) : static_cast<std::uint16_t>(crc >> 1);
        }
    }
    return crc;
}

Frame withCrc(Frame frame) {
    const std::uint16_t crc = crc16(frame);
    frame.push_back(static_cast<std::uint8_t>(crc & 0xFF));
    frame.push_back(static_cast<std::uint8_t>(crc >> 8));
    return frame;
}

bool crcMatches(std::span<const std::uint8_t> frame) {
    if (frame.size() < 3) {
        return false;
    }
    const std::uint16_t crc = crc16(frame.first(frame.size() - 2));
    return frame[frame.size() - 2] == (crc & 0xFF) && frame[frame.size() - 1] == (crc >> 8);
}

bool isWrite(int function) {
    return function == 15 || function == 16;
}

bool isCoilFunction(int function) {
    return function == 1 || function == 2 || function == 15;
}

int quantity(int function, int bytes) {
    return isCoilFunction(function) ? bytes * 8 : (bytes + 1) / 2;
}

Frame request(int slave, int function, int address, int bytes, std::span<const std::uint8_t> data) {
    Frame frame{static_cast<std::uint8_t>(slave), static_cast<std::uint8_t>(function)};
    put16(frame, address);
    const int count = quantity(function, bytes);
    put16(frame, count);
    if (function == 15) {
        frame.push_back(static_cast<std::uint8_t>(bytes)); // beyond 255 the slave sees a wrong count: exception 03
        frame.insert(frame.end(), data.begin(), data.end());
    } else if (function == 16) {
        frame.push_back(static_cast<std::uint8_t>(2 * count));
        for (int r = 0; r < count; ++r) {
            const std::size_t low = 2 * static_cast<std::size_t>(r);
            frame.push_back(low + 1 < data.size() ? data[low + 1] : 0); // the register's high byte first
            frame.push_back(data[low]);
        }
    }
    return withCrc(std::move(frame));
}

std::variant<Reply, Message> readReply(std::span<const std::uint8_t> sent, int bytes,
                                           std::span<const std::uint8_t> answer) {
    if (answer.size() < 5) {
        return message("modbus_answer_short", {std::to_string(answer.size())});
    }
    if (!crcMatches(answer)) {
        return message("modbus_answer_crc");
    }
    if (answer[0] != sent[0]) {
        return message("modbus_answer_other_slave", {std::to_string(answer[0]), std::to_string(sent[0])});
    }
    const int function = sent[1];
    if (answer[1] == (function | 0x80)) {
        if (answer.size() != 5) {
            return message("modbus_answer_exception_size");
        }
        return Reply{answer[2], {}};
    }
    if (answer[1] != function) {
        return message("modbus_answer_other_function", {std::to_string(answer[1]), std::to_string(function)});
    }
    if (isWrite(function)) {
        if (answer.size() != 8 || get16(answer, 2) != get16(sent, 2) || get16(answer, 4) != get16(sent, 4)) {
            return message("modbus_answer_write_echo");
        }
        return Reply{};
    }
    const std::size_t count = isCoilFunction(function) ? static_cast<std::size_t>(bytes)
                                                       : 2 * static_cast<std::size_t>(quantity(function, bytes));
    if (answer[2] != count || answer.size() != 3 + count + 2) {
        return message("modbus_answer_byte_count", {std::to_string(answer[2]), std::to_string(count)});
    }
    Reply reply;
    reply.data.reserve(static_cast<std::size_t>(bytes));
    if (isCoilFunction(function)) {
        reply.data.assign(answer.begin() + 3, answer.begin() + 3 + bytes);
        return reply;
    }
    for (std::size_t r = 0; 2 * r < static_cast<std::size_t>(bytes); ++r) {
        reply.data.push_back(answer[4 + 2 * r]); // the low byte: the first variable of the pair
        if (2 * r + 1 < static_cast<std::size_t>(bytes)) {
            reply.data.push_back(answer[3 + 2 * r]);
        }
    }
    return reply;
}

std::string hex(std::span<const std::uint8_t> frame) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    out.reserve(frame.size() * 3);
    for (std::uint8_t b : frame) {
        if (!out.empty()) {
            out += ' ';
        }
        out += kHex[b >> 4];
        out += kHex[b & 0xF];
    }
    return out;
}

} // namespace m350::devices::modbus
