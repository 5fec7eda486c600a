// The part of the Executor that runs the statements talking to devices beside the CNC: FANUC's
// POPEN, DPRNT, BPRNT, PCLOS and the M350's MSETDATA, MGETDATA. The records and registers go to
// the Peripherals; what they refuse becomes an alarm on the statement's line.
#include "core/macro/Executor.h"
#include "core/macro/PrintFormat.h"

#include <cmath>
#include <cstdio>

namespace m350::macro {

namespace {

constexpr char kEndOfBlock = '\n'; // FANUC sends LF as the end of each record (ISO)

void check(const std::optional<std::string>& refusal, std::uint32_t column) {
    if (refusal) {
        throw MacroError{AlarmCode::DeviceError, *refusal, column};
    }
}

} // namespace

void Executor::executeDeviceStatement(const gcode::Block& block) {
    using gcode::Control;
    const std::uint32_t column = block.controlColumn;
    Peripherals* devices = options_.peripherals;
    if (!devices) {
        throw MacroError{AlarmCode::DeviceError, "this machine has no external device or Modbus port", column};
    }
    // POPEN and PCLOS have no items: their `statement` is 0, which names nothing when no DPRNT came before
    const std::span<const gcode::StatementItem> items =
        block.control == Control::Popen || block.control == Control::Pclos
            ? std::span<const gcode::StatementItem>{}
            : program_.statements[block.statement];
    // A Modbus argument: a whole number from `low` to `high`.
    auto whole = [&](std::size_t k, const char* what, double low, double high) {
        const double v = evaluator_.number(items[k].value);
        if (std::abs(v - std::round(v)) > 1e-9 || v < low || v > high) {
            char range[64];
            std::snprintf(range, sizeof range, " must be a whole number from %.0f to %.0f, not %g", low, high, v);
            throw MacroError{AlarmCode::InvalidArgument, std::string(what) + range, items[k].column};
        }
        return static_cast<int>(std::lround(v));
    };
    switch (block.control) {
    case Control::Popen: check(devices->openOutput(), column); return;
    case Control::Pclos: check(devices->closeOutput(), column); return;
    case Control::Dprnt:
    case Control::Bprnt: {
        const bool binary = block.control == Control::Bprnt;
        std::string record;
        for (const gcode::StatementItem& item : items) {
            if (item.value == gcode::kNoExpr) {
                record += item.text;
                continue;
            }
            const Value value = evaluator_.evaluate(item.value);
            if (!binary) {
                record += formatDprnt(value, item.integerDigits, item.fractionDigits);
            } else if (auto bytes = formatBprnt(value, item.fractionDigits)) {
                record += *bytes;
            } else {
                throw MacroError{AlarmCode::InvalidArgument,
                                 "BPRNT: #" + std::to_string(evaluator_.variableNumber(item.value)) + " = " +
                                     std::to_string(value.number) + " with " + std::to_string(item.fractionDigits) +
                                     " decimals does not fit in 32 bits",
                                 item.column};
            }
        }
        record += kEndOfBlock;
        check(devices->output(binary ? "BPRNT" : "DPRNT", record), column);
        return;
    }
    case Control::MSetData: {
        const int slave = whole(0, "the slave address", 1, 247);
        const int address = whole(1, "the register address", 0, 65535);
        const int value = whole(2, "a 16-bit register value", -32768, 65535);
        check(devices->writeRegister(slave, address, static_cast<std::uint16_t>(value & 0xFFFF)), column);
        return;
    }
    case Control::MGetData: {
        const int slave = whole(0, "the slave address", 1, 247);
        const int address = whole(1, "the register address", 0, 65535);
        auto read = devices->readRegister(slave, address);
        if (auto* refusal = std::get_if<std::string>(&read)) {
            throw MacroError{AlarmCode::DeviceError, *refusal, column};
        }
        const int variable = evaluator_.variableNumber(items[2].value);
        evaluator_.writeVariable(variable, Value::of(std::get<std::uint16_t>(read)), {}, items[2].column);
        return;
    }
    default:
        throw MacroError{AlarmCode::DeviceError, "this statement is not simulated", column};
    }
}

} // namespace m350::macro
