// Modbus RTU frames byte by byte (the whole frames, CRC included, worked out apart from this code):
// the CRC against the Modbus specification's own examples, the
// frames MSETDATA and MGETDATA send (the byte values owners captured on a PC slave:
// fchabot-dxf/ddcs-pc-bridge), what the simulated slave answers, and how the master reads it.
#include "core/devices/ModbusRtu.h"
#include "core/devices/ModbusSlave.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace m350::devices;
using modbus::Frame;

Frame bytesOf(const std::string& hexText) {
    Frame out;
    for (std::size_t i = 0; i + 1 < hexText.size(); i += 3) {
        out.push_back(static_cast<std::uint8_t>(std::stoi(hexText.substr(i, 2), nullptr, 16)));
    }
    return out;
}

TEST(ModbusRtu, CrcMatchesTheSpecificationsExamples) {
    const std::string check = "123456789"; // CRC-16/MODBUS's check value
    EXPECT_EQ(modbus::crc16({reinterpret_cast<const std::uint8_t*>(check.data()), check.size()}), 0x4B37);
    // "Modbus over serial line" V1.02: read holding registers 108-110 of slave 17
    EXPECT_EQ(modbus::hex(modbus::withCrc(bytesOf("11 03 00 6B 00 03"))), "11 03 00 6B 00 03 76 87");
    EXPECT_EQ(modbus::hex(modbus::withCrc(bytesOf("01 03 00 00 00 0A"))), "01 03 00 00 00 0A C5 CD");
    EXPECT_TRUE(modbus::crcMatches(bytesOf("11 03 00 6B 00 03 76 87")));
    EXPECT_FALSE(modbus::crcMatches(bytesOf("11 03 00 6B 00 03 87 76")));
}

// MSETDATA[200,1,0,4,16,300] with #200-#203 = 11 22 33 44: the owners' slave logged holding
// register 0 = 5643 (22 << 8 | 11) and 1 = 11297 (44 << 8 | 33).
TEST(ModbusRtu, WriteRegistersPacksTwoVariablesARegisterLittleEndian) {
    const std::uint8_t vars[] = {11, 22, 33, 44};
    const Frame sent = modbus::request(1, 16, 0, 4, vars);
    EXPECT_EQ(modbus::hex(sent), "01 10 00 00 00 02 04 16 0B 2C 21 5A FD");
    ModbusSlave slave(1, {{{0, 0}, {1, 0}}, {}, {}, {}});
    auto answer = slave.answer(sent);
    ASSERT_TRUE(answer);
    EXPECT_EQ(modbus::hex(*answer), "01 10 00 00 00 02 41 C8");
    EXPECT_EQ(slave.memory().holding.at(0), 5643);
    EXPECT_EQ(slave.memory().holding.at(1), 11297);
    auto reply = modbus::readReply(sent, 4, *answer);
    ASSERT_TRUE(std::holds_alternative<modbus::Reply>(reply)) << std::get<m350::Message>(reply);
    EXPECT_EQ(std::get<modbus::Reply>(reply).exception, 0);
}

// An odd length: the last register's high byte is 0 on a write and left out on a read.
TEST(ModbusRtu, AnOddLengthFillsTheLastRegistersHighByteWithZero) {
    const std::uint8_t vars[] = {1, 2, 3};
    EXPECT_EQ(modbus::hex(modbus::request(5, 16, 0x2000, 3, vars)),
              modbus::hex(modbus::withCrc(bytesOf("05 10 20 00 00 02 04 02 01 00 03"))));
    const Frame sent = modbus::request(5, 3, 0x2000, 3, {});
    EXPECT_EQ(modbus::hex(sent), modbus::hex(modbus::withCrc(bytesOf("05 03 20 00 00 02"))));
    auto reply = modbus::readReply(sent, 3, modbus::withCrc(bytesOf("05 03 04 02 01 FF 03")));
    ASSERT_TRUE(std::holds_alternative<modbus::Reply>(reply)) << std::get<m350::Message>(reply);
    EXPECT_EQ(std::get<modbus::Reply>(reply).data, (std::vector<std::uint8_t>{1, 2, 3}));
}

// MGETDATA[200,1,10,4,3,300] against the owners' slave, seeded with registers 10 = 66 << 8 | 55
// and 11 = 88 << 8 | 77: #200-#203 = 55 66 77 88.
TEST(ModbusRtu, ReadHoldingRegistersUnpacksLowByteFirst) {
    const Frame sent = modbus::request(1, 3, 10, 4, {});
    EXPECT_EQ(modbus::hex(sent), "01 03 00 0A 00 02 E4 09");
    ModbusSlave slave(1, {{{10, 66 << 8 | 55}, {11, 88 << 8 | 77}}, {}, {}, {}});
    auto answer = slave.answer(sent);
    ASSERT_TRUE(answer);
    EXPECT_EQ(modbus::hex(*answer), "01 03 04 42 37 58 4D A4 70");
    auto reply = modbus::readReply(sent, 4, *answer);
    ASSERT_TRUE(std::holds_alternative<modbus::Reply>(reply)) << std::get<m350::Message>(reply);
    EXPECT_EQ(std::get<modbus::Reply>(reply).data, (std::vector<std::uint8_t>{55, 66, 77, 88}));
}

TEST(ModbusRtu, CoilsTakeTheBytesAsTheyAreEightCoilsAByte) {
    const std::uint8_t vars[] = {0x05, 0x80};
    const Frame sent = modbus::request(2, 15, 16, 2, vars);
    EXPECT_EQ(modbus::hex(sent), "02 0F 00 10 00 10 02 05 80 F6 B0");
    ModbusMemory memory;
    for (int a = 16; a < 32; ++a) {
        memory.coils[a] = false;
    }
    memory.discrete = {{0, true}, {1, false}, {2, false}, {3, true}, {4, false}, {5, false}, {6, false}, {7, true}};
    ModbusSlave slave(2, memory);
    auto answer = slave.answer(sent);
    ASSERT_TRUE(answer);
    EXPECT_EQ(modbus::hex(*answer), "02 0F 00 10 00 10 55 F1");
    EXPECT_TRUE(slave.memory().coils.at(16));
    EXPECT_FALSE(slave.memory().coils.at(17));
    EXPECT_TRUE(slave.memory().coils.at(18));
    EXPECT_TRUE(slave.memory().coils.at(31));
    const Frame readCoils = modbus::request(2, 1, 16, 2, {});
    auto coils = slave.answer(readCoils);
    ASSERT_TRUE(coils);
    EXPECT_EQ(modbus::hex(*coils), "02 01 02 05 80 FF 0C");
    const Frame readInputs = modbus::request(2, 2, 0, 1, {});
    auto inputs = slave.answer(readInputs);
    ASSERT_TRUE(inputs);
    EXPECT_EQ(std::get<modbus::Reply>(modbus::readReply(readInputs, 1, *inputs)).data,
              (std::vector<std::uint8_t>{0x89}));
}

TEST(ModbusRtu, TheSlaveAnswersExceptionsAsTheSpecificationSays) {
    ModbusSlave slave(1, {{{0, 1}, {1, 2}}, {}, {}, {}});
    struct Case {
        Frame request;
        const char* answer;
    };
    const std::uint8_t six[] = {1, 2, 3, 4, 5, 6};
    const Case cases[] = {
        {modbus::request(1, 3, 1, 4, {}), "01 83 02"},    // register 2 is not there
        {modbus::request(1, 4, 0, 2, {}), "01 84 01"},    // no input registers at all
        {modbus::request(1, 16, 0, 6, six), "01 90 02"},  // a write that reaches register 2 writes nothing
        {modbus::request(1, 3, 0, 252, {}), "01 83 03"},  // 126 registers: beyond a read's 125
        {modbus::withCrc(bytesOf("01 07")), "01 87 01"},  // a function it does not know
    };
    for (const Case& c : cases) {
        auto answer = slave.answer(c.request);
        ASSERT_TRUE(answer) << modbus::hex(c.request);
        EXPECT_EQ(modbus::hex(*answer), modbus::hex(modbus::withCrc(bytesOf(c.answer)))) << modbus::hex(c.request);
    }
    EXPECT_EQ(slave.memory().holding.at(0), 1);
    auto reply = modbus::readReply(cases[0].request, 4, *slave.answer(cases[0].request));
    EXPECT_EQ(std::get<modbus::Reply>(reply).exception, 2);
}

TEST(ModbusRtu, AFrameForAnotherSlaveOrWithABadCrcGetsNoAnswer) {
    ModbusSlave slave(1, {{{0, 1}}, {}, {}, {}});
    EXPECT_FALSE(slave.answer(modbus::request(2, 3, 0, 2, {})));
    Frame broken = modbus::request(1, 3, 0, 2, {});
    broken[3] ^= 1;
    EXPECT_FALSE(slave.answer(broken));
    EXPECT_TRUE(slave.answer(modbus::request(1, 3, 0, 2, {})));
}

TEST(ModbusRtu, TheMasterRefusesAnAnswerThatIsNotOneToItsRequest) {
    const Frame sent = modbus::request(1, 3, 0, 2, {});
    struct Case {
        Frame answer;
        const char* why;
    };
    Frame badCrc = modbus::withCrc(bytesOf("01 03 02 00 07"));
    badCrc.back() ^= 0xFF;
    const Case cases[] = {
        {bytesOf("01 03 02"), "fewer than any Modbus frame"},
        {badCrc, "CRC does not match"},
        {modbus::withCrc(bytesOf("02 03 02 00 07")), "comes from slave 2, not 1"},
        {modbus::withCrc(bytesOf("01 04 02 00 07")), "for function 4, not 3"},
        {modbus::withCrc(bytesOf("01 03 04 00 07 00 08")), "carries 4 bytes, not the 2 asked for"},
    };
    for (const Case& c : cases) {
        auto reply = modbus::readReply(sent, 2, c.answer);
        ASSERT_TRUE(std::holds_alternative<m350::Message>(reply)) << modbus::hex(c.answer);
        EXPECT_NE(std::get<m350::Message>(reply).english().find(c.why), std::string::npos) << std::get<m350::Message>(reply);
    }
    // the controller's alarm nests the reason and says it in the panel's language (no simulated
    // slave answers wrongly, so no run reaches it)
    auto reply = modbus::readReply(sent, 2, modbus::withCrc(bytesOf("02 03 02 00 07")));
    const m350::Message alarm = m350::message("modbus_bad_answer", {"MGETDATA", "1", m350::bilingual(std::get<m350::Message>(reply))});
    EXPECT_EQ(alarm.english(), "MGETDATA: slave 1's answer: the answer comes from slave 2, not 1");
    EXPECT_EQ(alarm.in(m350::MessageLanguage::Chinese), "MGETDATA：从站1的应答：应答来自从站2，而不是1");
}

} // namespace
