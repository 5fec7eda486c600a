#pragma once

#include "core/config/ModbusSlaves.h"
#include "core/devices/ModbusSlave.h"
#include "core/params/ParameterTable.h"
#include "core/common/HeadTail.h"
#include "core/controller/TraceWriter.h"
#include "core/machine/ScanMachine.h"
#include "core/macro/Peripherals.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace m350::controller {

// The devices beside the CNC that macro statements reach (macro::Peripherals):
// - FANUC's external output device (an RS-232 punch or printer): POPEN opens it, DPRNT and BPRNT
//   send records, PCLOS closes it. What it received collects in received() (m350-sim writes it into
//   a file), bounded by `limit` bytes: past it the first records and the newest are kept with a
//   line between them saying how much was left out. Each record goes to the trace as it is sent.
//   DPRNT or BPRNT while it is closed is an alarm, as on the FANUC-compatible controls that
//   document it.
// - the M350's Modbus RTU slaves (modbus.toml): with parameter 279 on, MSETDATA and MGETDATA send
//   a Modbus RTU frame (devices/ModbusRtu.h) that the slave it names answers from its tables in
//   memory (devices::ModbusSlave); each transfer goes to the trace with both frames in hex. A
//   slave modbus.toml does not declare is silent: the statement waits the controller's timeout
//   (16 s of virtual time), then alarms naming the slave (the controller itself would hang on
//   MGETDATA).
// A view that shows each record as it comes (the panel's system log) takes them with
// takeNewRecords(), which hands over every record whatever the limit leaves of received().
// While 断点加工 scans the blocks before its start line, POPEN and PCLOS open and close the device
// (its state, as outputs are scanned) but no record is sent, and a Modbus transfer makes the scan
// refuse (the slave is the world outside, which a scan does not reach).
class ExternalDevices : public macro::Peripherals {
public:
    // The records sent since the last takeNewRecords(), oldest first. Only the newest
    // kNewRecordsBudget bytes of them wait for a taker (a run nobody watches must stay bounded);
    // `missed` counts the older ones left out.
    struct NewRecords {
        std::vector<std::string> records;
        std::uint64_t missed = 0;
    };
    static constexpr std::size_t kNewRecordsBudget = 1u << 20;

    struct Context {
        const params::ParameterTable& parameters;
        machine::ScanMachine& scan;
        const std::unique_ptr<TraceWriter>& trace;
        std::function<double()> time;
        std::function<TraceSource()> source;
        std::function<void(double)> wait; // lets `seconds` of virtual time pass (a silent slave)
    };
    ExternalDevices(Context context, config::ModbusSlaves slaves, std::uint64_t limit);

    std::string received() const;
    bool outputOpened() const { return opened_; } // POPEN ran at least once
    // True once received() leaves records out: the output reached its limit.
    bool outputCapped() const { return receivedKept_.omitted() > 0; }
    NewRecords takeNewRecords();
    // A new run starts with the output device closed and no Modbus wait under way.
    void beginRun() {
        open_ = false;
        silentSlave_.reset();
    }

    std::optional<Message> openOutput() override;
    std::optional<Message> closeOutput() override;
    std::optional<Message> output(std::string_view statement, std::string_view record) override;
    std::variant<ModbusAnswer, ModbusPending, macro::MacroError> modbus(const ModbusRequest& request) override;

private:
    Context context_;
    std::map<int, devices::ModbusSlave> slaves_;
    std::optional<int> silentSlave_; // the slave whose answer a statement has waited for
    std::string receivedFirst_;
    HeadTail<std::string> receivedKept_;
    HeadTail<std::string> newRecords_{0, kNewRecordsBudget}; // no head: every record waits in its tail
    bool open_ = false;
    bool opened_ = false;
};

} // namespace m350::controller
