#include "core/controller/StatusBoard.h"

#include "core/common/EchoText.h"
#include "core/controller/MagazineDriver.h"
#include "core/controller/PanelStatus.h"
#include "core/devices/Magazine.h"
#include "core/gcode/Program.h"
#include "core/interp/ModalInterpreter.h"
#include "core/machine/SimulatedMachine.h"
#include "core/macro/Executor.h"
#include "core/params/ParameterLimits.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace m350::controller {

namespace {

// One modal group as the panel's modal line prints it: G00, G17, G80 ...
// to_chars, not snprintf: the modal line is written at every snapshot, ten numbers each time
void appendNumber(std::string& line, double value, int decimals) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, decimals).ptr;
    line.append(text, end);
}

void appendGWord(std::string& line, double code) {
    line += 'G';
    if (code == std::floor(code) && code >= 0.0 && code < 10.0) {
        line += '0'; // G00 .. G09, as the panel shows them
    }
    appendNumber(line, code, code == std::floor(code) ? 0 : 1);
}

} // namespace

StatusBoard::StatusBoard(Context context, const RunSettings& settings) : context_(context) {
    if (settings.trace) {
        trace_ = std::make_unique<TraceWriter>(*settings.trace, settings.traceLimit);
    }
}

std::optional<gcode::SourceLocation> StatusBoard::location() const {
    return context_.executor ? context_.executor->location() : std::nullopt;
}

TraceSource StatusBoard::source() const {
    if (context_.executor) {
        if (auto loc = context_.executor->location()) {
            return {context_.program.fileName(*loc), loc->line};
        }
    }
    return {};
}

void StatusBoard::postMessage(std::string text) {
    text = clipEcho(std::move(text));
    if (trace_) {
        trace_->message(context_.machine.time(), text, source());
    }
    messages_.add(std::move(text));
}

void StatusBoard::postMessage(const Message& words) {
    std::string text = words.english();
    if (trace_) {
        trace_->message(context_.machine.time(), text, source());
    }
    messages_.add(std::move(text), words);
}

void StatusBoard::postMessage(const Alarm& notice) {
    if (notice.messageId.empty()) {
        postMessage(notice.message);
        return;
    }
    std::string text = clipEcho(notice.message); // as the alarm says it
    if (trace_) {
        trace_->message(context_.machine.time(), text, source());
    }
    messages_.add(std::move(text), Message{notice.messageId, notice.messageArguments});
}

void StatusBoard::warn(const Alarm& warning) {
    postMessage(warning);
    statusLine_ = warning.message;
    notice_ = warning;
    warnings_.push_back(warning);
}

RunReport StatusBoard::report() const {
    RunReport out;
    switch (context_.state) {
    case RunState::Alarm:
    case RunState::EStop: out.status = RunStatus::Alarm; break;
    default: out.status = context_.executor ? RunStatus::Ok : RunStatus::Error; break;
    }
    out.alarm = context_.alarm;
    out.diagnostics = context_.diagnostics;
    out.machine = context_.machine.position();
    out.work = context_.interp.workPosition();
    out.tool = context_.magazine.spindleTool();
    out.warnings = warnings_;
    if (context_.toolDoubt.doubt()) {
        out.toolUnsure = context_.toolDoubt.notice();
    }
    const config::MachineConfig& config = context_.config;
    const devices::Magazine* magazine = context_.magazine.device();
    int capacity = config.dialect->id == gcode::DialectId::M350
                       ? params::magazineCapacity(config.parameters)
                       : magazine ? magazine->pocketCount() : std::clamp(config.magazineCapacity, 0, params::kMostPockets);
    // Without a magazine device every tool has its own pocket, empty while it is in the spindle.
    for (int pocket = 1; pocket <= capacity; ++pocket) {
        if (magazine) {
            out.pockets[pocket] = pocket <= magazine->pocketCount() ? magazine->pocketTool(pocket) : 0;
        } else {
            out.pockets[pocket] = pocket == out.tool ? 0 : pocket;
        }
    }
    if (magazine) {
        out.fallenTools = magazine->droppedTools();
    }
    for (int port = 1; port <= machine::kOutputCount; ++port) {
        out.outputs[static_cast<std::size_t>(port - 1)] = context_.machine.output(port);
    }
    out.messages = messages_.list();
    out.messageWords = messages_.words();
    out.messagesOmitted = messages_.omitted();
    out.simTime = context_.machine.time();
    out.blocks = context_.executor ? context_.executor->blocksExecuted() : 0;
    return out;
}

std::string StatusBoard::modalLine() const {
    const interp::ModalState& s = context_.interp.state();
    constexpr std::array<int, 8> kGroups{1, 2, 3, 5, 6, 7, 8, 9};
    ModalLineKey key{};
    for (std::size_t i = 0; i < kGroups.size(); ++i) {
        key[i] = s.groups[static_cast<std::size_t>(kGroups[i])];
    }
    key[8] = context_.interp.activeSlot();
    key[9] = s.rotating() ? 1.0 : 0.0;
    key[10] = s.feed;
    key[11] = s.spindleSpeed;
    // asked at every snapshot; the modes change at a few blocks of a run
    if (!modalLine_.empty() && key == modalKey_) {
        return modalLine_;
    }
    std::string line;
    for (int group : kGroups) {
        appendGWord(line, s.groups[static_cast<std::size_t>(group)]);
        line += ' ';
    }
    line += workSystemName(context_.interp.activeSlot());
    if (s.rotating()) {
        line += " G68";
    }
    line += " F";
    appendNumber(line, s.feed, 0);
    line += " S";
    appendNumber(line, s.spindleSpeed, 0);
    modalKey_ = key;
    modalLine_ = line;
    return line;
}

machine::SpindleState StatusBoard::spindleDisplay() const {
    machine::SpindleState state = context_.machine.spindleState();
    const int cycle = context_.interp.state().group(9);
    bool turning = state == machine::SpindleState::Forward || state == machine::SpindleState::Reverse;
    return turning && (cycle == 84 || cycle == 74) ? machine::SpindleState::Tap : state;
}

} // namespace m350::controller
