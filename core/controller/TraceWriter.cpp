#include "core/controller/TraceWriter.h"

#include "core/controller/AxesJson.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>

namespace m350::controller {

namespace {

void withSource(nlohmann::json& j, const TraceSource& source) {
    j["file"] = source.file;
    j["line"] = source.line;
}

constexpr std::uint64_t kMostTailBytes = 16ull << 20;
constexpr std::uint64_t kNoteBytes = 512; // room for the trace_truncated line

std::size_t tailBudget(std::uint64_t limit) {
    return static_cast<std::size_t>(std::min(limit / 4, kMostTailBytes));
}

} // namespace

TraceWriter::TraceWriter(std::ostream& out, std::uint64_t limit)
    : out_(out), limit_(limit),
      kept_(static_cast<std::size_t>(limit - tailBudget(limit) - std::min(limit - tailBudget(limit), kNoteBytes)),
            tailBudget(limit)) {}

void TraceWriter::writeLine(std::string line) {
    line += '\n';
    if (kept_.takeIntoHead(line.size())) {
        out_ << line;
    } else {
        const std::size_t size = line.size();
        kept_.keepInTail(std::move(line), size);
    }
}

void TraceWriter::finish() {
    if (finished_) {
        return;
    }
    finished_ = true;
    if (kept_.omitted() > 0) {
        nlohmann::json note{{"type", "trace_truncated"},
                            {"omitted_lines", kept_.omitted()},
                            {"omitted_bytes", kept_.omittedCost()},
                            {"limit_bytes", limit_},
                            {"note", "the trace reached its limit (--trace-limit): the first and the last lines "
                                     "are kept"}};
        out_ << note.dump() << '\n';
    }
    for (const auto& kept : kept_.tail()) {
        out_ << kept.piece;
    }
}

void TraceWriter::machineEvent(const machine::MachineEvent& e, const TraceSource& source) {
    using Type = machine::MachineEvent::Type;
    nlohmann::json j;
    j["t"] = e.start;
    switch (e.type) {
    case Type::Rapid:
    case Type::Feed:
    case Type::Arc:
        j["type"] = "move";
        j["kind"] = e.type == Type::Rapid ? "rapid" : e.type == Type::Feed ? "feed" : "arc";
        j["from"] = axesJson(e.from);
        j["to"] = axesJson(e.to);
        j["feed"] = e.feed;
        j["start"] = e.start;
        j["end"] = e.end;
        break;
    case Type::Dwell:
        j["type"] = "dwell";
        j["start"] = e.start;
        j["end"] = e.end;
        break;
    case Type::Io:
        j["type"] = "io";
        j["port"] = (e.port > 0 ? "OUT" : "IN") + std::string(std::abs(e.port) < 10 ? "0" : "") +
                    std::to_string(std::abs(e.port));
        j["level"] = e.level;
        break;
    case Type::Spindle:
        j["type"] = "spindle";
        j["state"] = std::string(machine::spindleStateName(e.spindle));
        j["rpm"] = e.rpm;
        break;
    case Type::Coolant:
        j["type"] = "coolant";
        j["on"] = e.level != 0;
        break;
    case Type::Auxiliary:
        j["type"] = "pmc";
        j["m"] = e.port;
        break;
    }
    withSource(j, source);
    writeLine(j.dump());
}

void TraceWriter::message(double time, std::string_view text, const TraceSource& source) {
    nlohmann::json j{{"t", time}, {"type", "message"}, {"text", std::string(text)}};
    withSource(j, source);
    writeLine(j.dump());
}

void TraceWriter::toolChange(double time, int from, int to, const TraceSource& source) {
    nlohmann::json j{{"t", time}, {"type", "toolchange"}, {"from", from}, {"to", to}};
    withSource(j, source);
    writeLine(j.dump());
}

void TraceWriter::lookAhead(double time, std::string_view code, const TraceSource& source) {
    nlohmann::json j{{"t", time}, {"type", "lookahead"}, {"code", std::string(code)}};
    withSource(j, source);
    writeLine(j.dump());
}

void TraceWriter::externalOutput(double time, std::string_view statement, std::string_view record,
                                 const TraceSource& source) {
    nlohmann::json j{{"t", time}, {"type", "output"}, {"statement", std::string(statement)}};
    if (statement == "DPRNT") {
        j["text"] = std::string(record.substr(0, record.find_last_not_of('\n') + 1));
    } else if (statement == "BPRNT") {
        static constexpr char kHex[] = "0123456789ABCDEF";
        std::string bytes;
        for (char c : record) {
            const auto b = static_cast<unsigned char>(c);
            bytes += std::string(bytes.empty() ? "" : " ") + kHex[b >> 4] + kHex[b & 0xF];
        }
        j["bytes"] = bytes;
    }
    withSource(j, source);
    writeLine(j.dump());
}

void TraceWriter::modbus(double time, const ModbusTransfer& transfer, const TraceSource& source) {
    nlohmann::json j{{"t", time},
                     {"type", "modbus"},
                     {"statement", transfer.statement},
                     {"slave", transfer.slave},
                     {"function", transfer.function},
                     {"address", transfer.address},
                     {"bytes", transfer.bytes},
                     {"request", transfer.request},
                     {"answer", transfer.answer ? nlohmann::json(*transfer.answer) : nlohmann::json()}};
    if (transfer.exception) {
        j["exception"] = *transfer.exception;
    }
    withSource(j, source);
    writeLine(j.dump());
}

void TraceWriter::runState(double time, std::string_view state) {
    nlohmann::json j{{"t", time}, {"type", std::string(state)}};
    writeLine(j.dump());
}

void TraceWriter::programStop(double time, std::string_view reason, const TraceSource& source) {
    nlohmann::json j{{"t", time}, {"type", "pause"}, {"reason", std::string(reason)}};
    withSource(j, source);
    writeLine(j.dump());
}

void TraceWriter::sensorWait(double time, std::string_view port, int level, const TraceSource& source) {
    nlohmann::json j{{"t", time}, {"type", "wait"}, {"port", std::string(port)}, {"level", level}};
    withSource(j, source);
    writeLine(j.dump());
}

void TraceWriter::alarm(double time, const Alarm& alarm) {
    nlohmann::json j{{"t", time},          {"type", "alarm"},      {"code", std::string(alarmKey(alarm.code))},
                     {"message", alarm.message}, {"file", alarm.file}, {"line", alarm.line},
                     {"column", alarm.column}};
    writeLine(j.dump());
}

} // namespace m350::controller
