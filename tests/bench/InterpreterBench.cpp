// m350-bench: throughput of the parser and the controller on the two workloads of the rs274
// comparison (tests/bench/compare_rs274.sh generates the same programs):
//   g1    200,000 lines `G1 X.. Y.. Z.. F1000`, then M30
//   loop  a 200,000-iteration WHILE loop with arithmetic, SIN and SQRT, then M30
// Benchmarks, not tests: they report items/s (lines or loop iterations) and never judge the speed.
// Each one checks its run ended normally and skips with an error otherwise.
//
//   Parse_*         gcode::Parser alone, from an in-memory string (no file, no controller)
//   Execute_*       Controller::run() on a controller already loaded (load is not timed)
//   ParseExecute_*  what `m350-sim run` does: Controller + loadFile (read + parse) + run()
#include "core/config/MachineConfig.h"
#include "core/controller/Controller.h"
#include "core/gcode/Diagnostic.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/Parser.h"
#include "core/gcode/Program.h"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <system_error>
#include <unistd.h>
#include <utility>
#include <variant>

namespace {

using namespace m350;

constexpr int kG1Lines = 200000;
constexpr int kLoopIterations = 200000;

enum class Workload { G1, Loop };

const gcode::Dialect& dialectOf(gcode::DialectId id) {
    return id == gcode::DialectId::Fanuc ? gcode::Dialect::fanuc() : gcode::Dialect::m350();
}

// Keep in step with compare_rs274.sh (its awk line is the same format).
std::string g1Program(int lines) {
    std::string text;
    text.reserve(static_cast<std::size_t>(lines) * 36 + 8);
    char line[96];
    for (int i = 0; i < lines; ++i) {
        int n = std::snprintf(line, sizeof line, "G1 X%d.123 Y%d.456 Z-%d.789 F1000\n", i % 100, (i * 7) % 100,
                              i % 10);
        text.append(line, static_cast<std::size_t>(n));
    }
    text += "M30\n";
    return text;
}

std::string loopProgram(int iterations, gcode::DialectId id) {
    const char* less = id == gcode::DialectId::Fanuc ? "LT" : "<";
    return "#1=0\n#2=0\nWHILE [#1 " + std::string(less) + " " + std::to_string(iterations) +
           "] DO1\n#2=SIN[#1]*SQRT[#1]+#2/2\n#1=#1+1\nEND1\nM30\n";
}

std::string programText(Workload workload, gcode::DialectId id) {
    return workload == Workload::G1 ? g1Program(kG1Lines) : loopProgram(kLoopIterations, id);
}

int itemsPerRun(Workload workload) { return workload == Workload::G1 ? kG1Lines : kLoopIterations; }

// A generated program written once to a temp file (Controller::loadFile takes a path), removed at exit.
class TempProgram {
public:
    TempProgram(const std::string& name, const std::string& text)
        : path_(std::filesystem::temp_directory_path() /
                ("m350-bench-" + std::to_string(::getpid()) + "-" + name + ".nc")) {
        std::ofstream out(path_, std::ios::binary | std::ios::trunc);
        out << text;
        ok_ = static_cast<bool>(out);
    }
    ~TempProgram() {
        std::error_code ec;
        std::filesystem::remove(path_, ec);
    }
    TempProgram(const TempProgram&) = delete;
    TempProgram& operator=(const TempProgram&) = delete;

    std::string path() const { return path_.string(); }
    bool ok() const { return ok_; }

private:
    std::filesystem::path path_;
    bool ok_ = false;
};

const TempProgram& programFile(Workload workload, gcode::DialectId id) {
    static std::map<std::pair<Workload, gcode::DialectId>, std::unique_ptr<TempProgram>> files;
    auto& slot = files[{workload, id}];
    if (!slot) {
        std::string name = std::string(workload == Workload::G1 ? "g1" : "loop") + "-" +
                           std::string(dialectOf(id).name);
        slot = std::make_unique<TempProgram>(name, programText(workload, id));
    }
    return *slot;
}

// The bundled machine folder `m350-sim --dialect X` would use; a bare config if it cannot load.
const config::MachineConfig& machineConfig(gcode::DialectId id) {
    static std::map<gcode::DialectId, config::MachineConfig> configs;
    auto it = configs.find(id);
    if (it == configs.end()) {
        std::string name = id == gcode::DialectId::Fanuc ? "fanuc-0i" : config::kDefaultMachine;
        auto loaded = config::loadMachineFolder(config::bundledMachinesDirectory() + "/" + name);
        config::MachineConfig cfg;
        if (auto* found = std::get_if<config::MachineConfig>(&loaded)) {
            cfg = std::move(*found);
        }
        cfg.dialect = &dialectOf(id);
        it = configs.emplace(id, std::move(cfg)).first;
    }
    return it->second;
}

controller::RunSettings runSettings() {
    controller::RunSettings settings;
    settings.maxSimTime = 1e9; // moves and blocks cost virtual time; never stop these runs for it
    return settings;
}

// Empty when the run did what the workload says; otherwise why not.
std::string checkRun(Workload workload, controller::Controller& controller, const controller::RunReport& report) {
    if (report.status != controller::RunStatus::Ok) {
        return report.alarm ? "run alarmed: " + report.alarm->message : "run ended in error";
    }
    if (workload == Workload::G1 && report.blocks < static_cast<std::uint64_t>(kG1Lines)) {
        return "only " + std::to_string(report.blocks) + " blocks executed";
    }
    if (workload == Workload::Loop && controller.variable(1).asNumber() != kLoopIterations) {
        return "loop counter #1 ended at " + std::to_string(controller.variable(1).asNumber());
    }
    return {};
}

void setCounters(benchmark::State& state, Workload workload, std::size_t bytes) {
    state.SetItemsProcessed(state.iterations() * itemsPerRun(workload));
    if (workload == Workload::G1) { // the loop's few bytes of source say nothing
        state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(bytes));
    }
    state.SetLabel(workload == Workload::G1 ? "items = G1 lines" : "items = loop iterations");
}

// Parser alone: text -> Program.
void Parse(benchmark::State& state, Workload workload, gcode::DialectId id) {
    const gcode::Dialect& dialect = dialectOf(id);
    const std::string text = programText(workload, id);
    for (auto _ : state) {
        gcode::Program program;
        gcode::Parser parser(dialect);
        parser.addFile(program, "bench.nc", text, gcode::FileRole::Main);
        parser.finish(program);
        if (gcode::hasBlockingError(parser.diagnostics())) {
            state.SkipWithError(("parse error: " + parser.diagnostics().front().message).c_str());
            break;
        }
        benchmark::DoNotOptimize(program.blocks.size());
        benchmark::ClobberMemory();
    }
    setCounters(state, workload, text.size());
}

// Controller::run() only; the controller is built and loaded with the timer paused.
void Execute(benchmark::State& state, Workload workload, gcode::DialectId id) {
    const TempProgram& file = programFile(workload, id);
    if (!file.ok()) {
        state.SkipWithError("cannot write the temp program");
        return;
    }
    for (auto _ : state) {
        state.PauseTiming();
        auto controller = std::make_unique<controller::Controller>(machineConfig(id), runSettings());
        bool loaded = controller->loadFile(file.path());
        state.ResumeTiming();
        if (!loaded) {
            state.SkipWithError("loadFile failed");
            break;
        }
        controller::RunReport report = controller->run();
        state.PauseTiming();
        std::string why = checkRun(workload, *controller, report);
        controller.reset();
        state.ResumeTiming();
        if (!why.empty()) {
            state.SkipWithError(why.c_str());
            break;
        }
    }
    setCounters(state, workload, programText(workload, id).size());
}

// What `m350-sim run` does, without process start-up and JSON: build, load (read + parse), run.
void ParseExecute(benchmark::State& state, Workload workload, gcode::DialectId id) {
    const TempProgram& file = programFile(workload, id);
    if (!file.ok()) {
        state.SkipWithError("cannot write the temp program");
        return;
    }
    for (auto _ : state) {
        controller::Controller controller(machineConfig(id), runSettings());
        if (!controller.loadFile(file.path())) {
            state.SkipWithError("loadFile failed");
            break;
        }
        controller::RunReport report = controller.run();
        if (std::string why = checkRun(workload, controller, report); !why.empty()) {
            state.SkipWithError(why.c_str());
            break;
        }
        benchmark::DoNotOptimize(report.blocks);
    }
    setCounters(state, workload, programText(workload, id).size());
}

using gcode::DialectId;

BENCHMARK_CAPTURE(Parse, g1_fanuc, Workload::G1, DialectId::Fanuc)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Parse, g1_m350, Workload::G1, DialectId::M350)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Execute, g1_fanuc, Workload::G1, DialectId::Fanuc)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Execute, loop_fanuc, Workload::Loop, DialectId::Fanuc)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Execute, loop_m350, Workload::Loop, DialectId::M350)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ParseExecute, g1_fanuc, Workload::G1, DialectId::Fanuc)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ParseExecute, g1_m350, Workload::G1, DialectId::M350)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ParseExecute, loop_fanuc, Workload::Loop, DialectId::Fanuc)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ParseExecute, loop_m350, Workload::Loop, DialectId::M350)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
