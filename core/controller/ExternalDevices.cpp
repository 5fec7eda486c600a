#include "core/controller/ExternalDevices.h"

#include "core/params/ParameterNumbers.h"

namespace m350::controller {

ExternalDevices::ExternalDevices(Context context, config::ModbusSlaves slaves, std::uint64_t limit)
    : context_(std::move(context)), slaves_(std::move(slaves)),
      receivedKept_(static_cast<std::size_t>(limit - limit / 4), static_cast<std::size_t>(limit / 4)) {}

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

std::optional<std::string> ExternalDevices::openOutput() {
    open_ = true;
    opened_ = true;
    if (context_.trace && !context_.scan.scanning()) {
        context_.trace->externalOutput(context_.time(), "POPEN", {}, context_.source());
    }
    return std::nullopt;
}

std::optional<std::string> ExternalDevices::closeOutput() {
    open_ = false;
    if (context_.trace && !context_.scan.scanning()) {
        context_.trace->externalOutput(context_.time(), "PCLOS", {}, context_.source());
    }
    return std::nullopt;
}

std::optional<std::string> ExternalDevices::output(std::string_view statement, std::string_view record) {
    if (!open_) {
        return std::string(statement) + " without POPEN: the external output device is closed (open it with POPEN "
                                        "before " + std::string(statement) + ", close it with PCLOS)";
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

std::optional<std::string> ExternalDevices::modbusRefusal(const char* statement, int slave, int address) {
    if (context_.parameters.get(param::kModbusRtu) == 0.0) {
        return std::string(statement) + ": Modbus RTU is off (parameter 279 = 0)";
    }
    auto found = slaves_.holding.find(slave);
    if (found == slaves_.holding.end()) {
        return std::string(statement) + ": Modbus slave " + std::to_string(slave) +
               " does not answer (the machine folder's modbus.toml has no [slave." + std::to_string(slave) +
               ".holding])";
    }
    if (found->second.count(address) == 0) {
        return std::string(statement) + ": slave " + std::to_string(slave) + " has no holding register " +
               std::to_string(address) + " (Modbus exception 02, illegal data address)";
    }
    if (context_.scan.scanning()) {
        context_.scan.refuse(std::string(statement) + " talks to Modbus slave " + std::to_string(slave));
    }
    return std::nullopt;
}

std::optional<std::string> ExternalDevices::writeRegister(int slave, int address, std::uint16_t value) {
    if (auto refusal = modbusRefusal("MSETDATA", slave, address)) {
        return refusal;
    }
    if (context_.scan.scanning()) {
        return std::nullopt;
    }
    slaves_.holding[slave][address] = value;
    if (context_.trace) {
        context_.trace->modbus(context_.time(), "write", slave, address, value, context_.source());
    }
    return std::nullopt;
}

std::variant<std::uint16_t, std::string> ExternalDevices::readRegister(int slave, int address) {
    if (auto refusal = modbusRefusal("MGETDATA", slave, address)) {
        return *refusal;
    }
    const std::uint16_t value = slaves_.holding[slave][address];
    if (context_.trace && !context_.scan.scanning()) {
        context_.trace->modbus(context_.time(), "read", slave, address, value, context_.source());
    }
    return value;
}

} // namespace m350::controller
