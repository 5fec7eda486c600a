#pragma once

#include "core/common/Alarm.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/Program.h"
#include "core/macro/BlockSink.h"
#include "core/macro/CallCodes.h"
#include "core/macro/Evaluator.h"
#include "core/macro/MachineAccess.h"
#include "core/macro/Peripherals.h"
#include "core/macro/VariableStore.h"

#include <array>
#include <map>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace m350::macro {

// Executes a parsed Program one block at a time: assignments, IF/GOTO/WHILE, calls and returns.
// Ordinary words go to the BlockSink (the modal interpreter). A run-time error becomes an Alarm
// that names file, line and column; the variables stay as they were for inspection.
class Executor {
public:
    struct Options {
        // Codes the machine makes call programs beyond the dialect's own rules: [codes] M6 = 9001,
        // a FANUC's parameters 6050-6091 (config::MachineConfig::callCodes).
        CallCodes callCodes;
        bool blockDelete = false; // optional block skip switch: skip '/' blocks when on
        // The external output device and Modbus slaves (none: their statements alarm).
        Peripherals* peripherals = nullptr;
    };

    enum class State { Idle, Running, Finished, Alarmed };

    Executor(const gcode::Program& program, const gcode::Dialect& dialect, VariableStore& store,
             MachineAccess& machine, BlockSink& sink, Options options);

    // Starts the unit (the main program, or an MDI line set); false when there is none.
    bool start(std::uint32_t unit);
    State step();

    State state() const { return state_; }
    const std::optional<Alarm>& alarm() const { return alarm_; }
    // The block being executed (or last executed).
    std::optional<gcode::SourceLocation> location() const;
    std::size_t callDepth() const { return frames_.size(); }
    // Whether a tool change program runs: the M350's T program (O20000) or the machine's M06
    // handler (FANUC's O9001). Its moves carry the tool, they do not cut with it.
    bool changingTool() const { return frames_.size() > 1 && changingToolInCall(); } // asked for every move
    std::uint64_t blocksExecuted() const { return blocksExecuted_; }
    // The blocks whose words reached the machine (the BlockSink): what single block stops after.
    std::uint64_t machineBlocksExecuted() const { return machineBlocks_; }
    // The main program's side of the run, for 断点加工: the block of the started unit that runs
    // now (the call that is running, when inside one), how many of its blocks have started, and
    // the block it will start next while no call is active.
    std::optional<std::uint32_t> mainBlock() const { return mainStarted_ ? std::optional(mainBlock_) : std::nullopt; }
    std::uint64_t mainBlocksStarted() const { return mainStarted_; }
    std::optional<std::uint32_t> nextMainBlock() const {
        return frames_.size() == 1 && state_ == State::Running ? std::optional(frames_.front().pc) : std::nullopt;
    }

    // Stops at once with an alarm raised from outside (sim-time limit, E-stop, a device).
    void raise(AlarmCode code, std::string message);
    void raise(AlarmCode code, const Message& words);

private:
    struct Frame {
        std::uint32_t unit = 0;
        std::uint32_t pc = 0;
        std::int64_t repeatsLeft = 1;
        bool ownsLocals = false;
        std::int32_t handledCode = -1; // 'T', 'M' or 'G' code this frame handles, to avoid recursion
    };
    struct Call {
        std::uint32_t unit = 0;
        std::int64_t repeats = 1;
        bool opensLocals = true;
        std::int32_t handledCode = -1;
        std::vector<std::pair<int, double>> arguments; // local number, value
    };

    void executeBlock(const gcode::Block& block, std::size_t frameIndex);
    void executeOrdinary(const gcode::Block& block, std::size_t frameIndex);
    // ExecutorStatements.cpp; false while the statement waits (it runs again at the next step)
    bool executeDeviceStatement(const gcode::Block& block);
    bool modbusTransfer(bool write, std::span<const gcode::StatementItem> items, std::uint32_t column);
    // Whether any word of the block may start a call; most blocks (G1 X.. Y..) do not, and skip the
    // call planning. Asked for every block: a block with no T, no other codes and no handler
    // cycle active is answered here on its code bits.
    bool mayCall(const EvaluatedBlock& block) const {
        if (!handlerCycle_ && !block.has('T') && !block.otherCodes && (block.letters & addressLetters_) == 0) {
            return block.gCodes.meets(callingG_) || block.mCodes.meets(callingM_);
        }
        return mayCallInFull(block);
    }
    bool mayCallInFull(const EvaluatedBlock& block) const;
    bool otherCodeMayCall(const EvaluatedBlock& block) const;
    void indexCallingCodes();
    bool changingToolInCall() const;
    bool sendToSink(const EvaluatedBlock& block, std::size_t frameIndex);
    void jumpToLabel(std::size_t frameIndex, double label, std::uint32_t column);
    void returnFromFrame(std::optional<double> label, std::uint32_t column, bool explicitM99);
    void pushCall(const Call& call, std::uint32_t column);
    bool handlingCode(std::int32_t code) const;
    // Whether a frame a code opened runs (FANUC: its G and M codes then call nothing).
    bool inCodeCall() const;
    // The program a machine-configured code calls, or nullptr when it calls none here.
    const CodeCall* configuredCall(char letter, int code) const;
    // FANUC 6090/6091: each word of a calling address is taken out, its value stored, its call planned.
    void takeAddressCalls(std::vector<WordValue>& words, std::vector<Call>& calls, std::uint32_t& callColumn);
    std::uint32_t programUnit(double number, const char* how, std::uint32_t column) const;
    std::optional<std::uint32_t> handlerFor(char letter, int code) const;
    void indexHandlers();
    bool isUserFile(std::uint32_t file) const;
    void nameCaller(Alarm& alarm) const;
    static void takeArguments(std::vector<WordValue>& words, const std::array<std::int8_t, 26>& map,
                              std::vector<std::pair<int, double>>& out, bool codesAreArguments);
    // Canned cycles run by handler programs (ExecutorCycles.cpp).
    bool cycleHandlerCall(int code) const;
    void prepareCycleCall(Call& call, int code, const std::vector<WordValue>& blockWords, std::uint32_t column);
    std::optional<Call> repeatCycle(std::vector<WordValue>& words, const std::array<std::int8_t, 26>& map);

    const gcode::Program& program_;
    const gcode::Dialect& dialect_;
    VariableStore& store_;
    MachineAccess& machine_;
    BlockSink& sink_;
    Options options_;
    Evaluator evaluator_;

    std::vector<Frame> frames_;
    EvaluatedBlock scratch_;
    // Handler programs of G and M codes 0..999 (unit index, -1 none), looked up once, not per block.
    std::vector<std::int32_t> gHandlers_;
    std::vector<std::int32_t> mHandlers_;
    std::optional<std::uint32_t> tCodeUnit_;
    CodeBits callingG_; // whole codes that start a call (indexCallingCodes)
    CodeBits callingM_;
    std::uint32_t addressLetters_ = 0; // letters that call (FANUC 6090/6091), bit (letter - 'A')
    State state_ = State::Idle;
    std::optional<Alarm> alarm_;
    std::uint32_t current_ = 0;
    bool hasCurrent_ = false;
    std::uint64_t blocksExecuted_ = 0;
    std::uint64_t machineBlocks_ = 0;
    std::uint32_t mainBlock_ = 0;
    std::uint64_t mainStarted_ = 0;
    // The canned cycle a handler program runs, kept modal until G80 or G00-G03.
    struct HandlerCycle {
        std::int32_t key = 0;
        std::uint32_t unit = 0;
        std::map<int, double> arguments; // local -> value, as the cycle's blocks gave them
        double initialLevel = 0.0;       // work Z when the cycle began
    };
    std::optional<HandlerCycle> handlerCycle_;
};

} // namespace m350::macro
