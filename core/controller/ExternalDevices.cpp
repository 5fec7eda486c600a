#include "core/controller/ExternalDevices.h"

#include "core/gcode/ModbusStatement.h"
#include "core/params/ParameterNumbers.h"

#include <cstdio>

namespace m350::controller {

ExternalDevices::ExternalDevices(Context context, config::ModbusSlaves slaves, std::uint64_t limit)
    : context_(std::move(context)),
      receivedKept_(static_cast<std::size_t>(limit - limit / 4), static_cast<std::size_t>(limit / 4)) {
    for (auto& [address, memory] : slaves.slaves) {
        slaves_.emplace(address, devices::ModbusSlave(address, std::move(memory)));
    }
}

std::string ExternalDevices::received() const {
    std::string out = receivedFirst_;
    if (receivedKept_.omitted() > 0) {
        out += "\n... " + std::to_string(receivedKept_.omitted()) + " records (" +
               std::to_string(receivedKept_.omittedCost()) + " bytes) omitted: the output reached its limit; the "
               "first and the last records are kept ...\n";
    }
    for (const auto& kept : receivedKept_.tail()) {
        out += kept.piece;
    }
    return out;
}

ExternalDevices::NewRecords ExternalDevices::takeNewRecords() {
    NewRecords out;
    out.records.reserve(newRecords_.tail().size());
    for (const auto& kept : newRecords_.tail()) {
        out.records.push_back(kept.piece);
    }
    out.missed = newRecords_.omitted();
    newRecords_.clear();
    return out;
}

std::optional<Message> ExternalDevices::openOutput() {
    open_ = true;
    opened_ = true;
    if (context_.trace && !context_.scan.scanning()) {
        context_.trace->externalOutput(context_.time(), "POPEN", {}, context_.source());
    }
    return std::nullopt;
}

std::optional<Message> ExternalDevices::closeOutput() {
    open_ = false;
    if (context_.trace && !context_.scan.scanning()) {
        context_.trace->externalOutput(context_.time(), "PCLOS", {}, context_.source());
    }
    return std::nullopt;
}

std::optional<Message> ExternalDevices::output(std::string_view statement, std::string_view record) {
    if (!open_) {
        return message("output_without_popen", {std::string(statement)});
    }
    if (context_.scan.scanning()) {
        return std::nullopt; // sent when the program ran up to here, not again
    }
    if (receivedKept_.takeIntoHead(record.size())) {
        receivedFirst_ += record;
    } else {
        receivedKept_.keepInTail(std::string(record), record.size());
    }
    newRecords_.keepInTail(std::string(record), record.size());
    if (context_.trace) {
        context_.trace->externalOutput(context_.time(), statement, record, context_.source());
    }
    return std::nullopt;
}

std::variant<macro::Peripherals::ModbusAnswer, macro::Peripherals::ModbusPending, macro::MacroError>
ExternalDevices::modbus(const ModbusRequest& request) {
    const std::string name = gcode::ModbusStatement::name(request.write);
    const std::string slave = std::to_string(request.slave);
    if (context_.parameters.get(param::kModbusRtu) == 0.0) {
        return macro::MacroError::of(AlarmCode::DeviceError, message(request.write ? "modbus_off_write" : "modbus_off_read"));
    }
    if (context_.scan.scanning()) {
        context_.scan.refuse(message("scan_modbus", {name, slave}));
        return ModbusAnswer{};
    }
    const devices::modbus::Frame sent =
        devices::modbus::request(request.slave, request.function, request.address, request.bytes, request.data);
    auto found = slaves_.find(request.slave);
    const std::optional<devices::modbus::Frame> answer =
        found != slaves_.end() ? found->second.answer(sent) : std::nullopt;
    TraceWriter::ModbusTransfer transfer{name,         request.slave, request.function, request.address,
                                         request.bytes, devices::modbus::hex(sent), std::nullopt, std::nullopt};
    if (!answer) {
        if (silentSlave_ != request.slave) {
            silentSlave_ = request.slave; // the statement runs again when the wait is over
            context_.wait(gcode::ModbusStatement::kTimeout);
            return ModbusPending{};
        }
        silentSlave_.reset();
        if (context_.trace) {
            context_.trace->modbus(context_.time(), transfer, context_.source());
        }
        char seconds[16];
        std::snprintf(seconds, sizeof seconds, "%.0f", gcode::ModbusStatement::kTimeout);
        return macro::MacroError::of(AlarmCode::DeviceError,
                                     message(request.write ? "modbus_write_no_answer" : "modbus_read_no_answer",
                                             {slave, seconds}));
    }
    auto reply = devices::modbus::readReply(sent, request.bytes, *answer);
    transfer.answer = devices::modbus::hex(*answer);
    if (auto* read = std::get_if<devices::modbus::Reply>(&reply)) {
        transfer.exception = read->exception;
    }
    if (context_.trace) {
        context_.trace->modbus(context_.time(), transfer, context_.source());
    }
    if (auto* why = std::get_if<Message>(&reply)) {
        return macro::MacroError::of(AlarmCode::DeviceError, message("modbus_bad_answer", {name, slave, bilingual(*why)}));
    }
    auto& read = std::get<devices::modbus::Reply>(reply);
    return ModbusAnswer{read.exception, std::move(read.data)};
}

} // namespace m350::controller
