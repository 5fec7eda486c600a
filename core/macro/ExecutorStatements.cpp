// The part of the Executor that runs the statements talking to devices beside the CNC: FANUC's
// POPEN, DPRNT, BPRNT, PCLOS and the M350's MSETDATA, MGETDATA. The records and registers go to
// the Peripherals; what they refuse becomes an alarm on the statement's line.
#include "core/gcode/ModbusStatement.h"
#include "core/macro/Executor.h"
#include "core/macro/PrintFormat.h"

#include <cmath>
#include <cstdio>

namespace m350::macro {

namespace {

constexpr char kEndOfBlock = '\n'; // FANUC sends LF as the end of each record (ISO)

void check(const std::optional<Message>& refusal, std::uint32_t column) {
    if (refusal) {
        throw MacroError::of(AlarmCode::DeviceError, *refusal, column);
    }
}

} // namespace

bool Executor::executeDeviceStatement(const gcode::Block& block) {
    using gcode::Control;
    const std::uint32_t column = block.controlColumn;
    Peripherals* devices = options_.peripherals;
    if (!devices) {
        throw MacroError::of(AlarmCode::DeviceError, message("no_device_port"), column);
    }
    // POPEN and PCLOS have no items: their `statement` is 0, which names nothing when no DPRNT came before
    const std::span<const gcode::StatementItem> items =
        block.control == Control::Popen || block.control == Control::Pclos
            ? std::span<const gcode::StatementItem>{}
            : program_.statements[block.statement];
    switch (block.control) {
    case Control::Popen: check(devices->openOutput(), column); return true;
    case Control::Pclos: check(devices->closeOutput(), column); return true;
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
                throw MacroError::of(AlarmCode::InvalidArgument,
                                     message("bprnt_too_big", {std::to_string(evaluator_.variableNumber(item.value)),
                                                               std::to_string(value.number),
                                                               std::to_string(item.fractionDigits)}),
                                     item.column);
            }
        }
        record += kEndOfBlock;
        check(devices->output(binary ? "BPRNT" : "DPRNT", record), column);
        return true;
    }
    case Control::MSetData:
    case Control::MGetData: return modbusTransfer(block.control == Control::MSetData, items, column);
    default:
        throw MacroError::of(AlarmCode::DeviceError, message("statement_not_simulated"), column);
    }
}

// MSETDATA[X1..X6] and MGETDATA[X1..X6] (gcode/ModbusStatement.h): #X1.. carry one byte each; the
// slave's exception code goes into #X6, 0 when it did what was asked (MGETDATA then fills #X1..).
bool Executor::modbusTransfer(bool write, std::span<const gcode::StatementItem> items, std::uint32_t column) {
    using gcode::ModbusStatement;
    int value[ModbusStatement::kCount] = {};
    for (int k = 0; k < ModbusStatement::kCount; ++k) {
        const gcode::StatementItem& item = items[static_cast<std::size_t>(k)];
        const double v = evaluator_.number(item.value);
        if (auto problem = ModbusStatement::argumentProblem(write, k, v)) {
            throw MacroError::of(AlarmCode::InvalidArgument, *problem, item.column);
        }
        value[k] = static_cast<int>(std::lround(v));
    }
    const int first = value[ModbusStatement::FirstVariable];
    const int bytes = value[ModbusStatement::Bytes];
    if (auto problem = ModbusStatement::spanProblem(write, first, bytes)) {
        throw MacroError::of(AlarmCode::InvalidArgument, *problem, items[ModbusStatement::Bytes].column);
    }
    Peripherals::ModbusRequest request{write, value[ModbusStatement::Slave], value[ModbusStatement::Function],
                                       value[ModbusStatement::Address], bytes, {}};
    const std::uint32_t firstColumn = items[ModbusStatement::FirstVariable].column;
    if (write) {
        request.data.reserve(static_cast<std::size_t>(bytes));
        for (int n = first; n < first + bytes; ++n) {
            const double v = evaluator_.readVariable(n, firstColumn).asNumber();
            if (std::abs(v - std::round(v)) > 1e-9 || v < 0 || v > 255) {
                char text[32];
                std::snprintf(text, sizeof text, "%.10g", v);
                throw MacroError::of(AlarmCode::InvalidArgument, message("msetdata_byte", {std::to_string(n), text}),
                                     firstColumn);
            }
            request.data.push_back(static_cast<std::uint8_t>(std::lround(v)));
        }
    }
    auto result = options_.peripherals->modbus(request);
    if (std::holds_alternative<Peripherals::ModbusPending>(result)) {
        return false;
    }
    if (auto* alarm = std::get_if<MacroError>(&result)) {
        MacroError error = std::move(*alarm);
        error.column = error.column != 0 ? error.column : column;
        throw error;
    }
    const Peripherals::ModbusAnswer& answer = std::get<Peripherals::ModbusAnswer>(result);
    if (!write && answer.exception == 0) {
        for (std::size_t i = 0; i < answer.data.size(); ++i) {
            evaluator_.writeVariable(first + static_cast<int>(i), Value::of(answer.data[i]), {}, firstColumn);
        }
    }
    evaluator_.writeVariable(value[ModbusStatement::ExceptionVariable], Value::of(answer.exception), {},
                             items[ModbusStatement::ExceptionVariable].column);
    return true;
}

} // namespace m350::macro
