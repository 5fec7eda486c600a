// The machine view's preview (core/preview): how long a program's path takes to build and how much
// memory it takes a move, on the mould-like programs of issue 27 (G1/G2/G3 lines a CAM system
// writes). Benchmarks, not tests: they report, never judge.
//   Preview_1M    1,000,000 lines, two thirds G1, one third G2/G3 arcs: buildPreview() whole
//   Preview_10M   10,000,000 lines of the same (run it alone: --benchmark_filter=Preview_10M)
//   LevelFrame_1M the work a frame does at 1M moves before painting: the level for the scale and
//                 the points of the chunks in view (the whole path, then a tenth of it)
// Counters: bytes_per_move (path and levels together, capacities), moves, peak_rss_mb.
#include "core/gcode/Dialect.h"
#include "core/params/ParameterNumbers.h"
#include "core/preview/PreviewBuilder.h"
#include "tests/bench/MouldProgram.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <sys/resource.h>
#include <unistd.h>

namespace {

using namespace m350;
using bench::program;

config::MachineConfig machine() {
    config::MachineConfig config;
    config.name = "preview bench";
    config.dialect = &gcode::Dialect::m350();
    config.parameters.set(param::kMagazineCapacity, 16);
    config.parameters.set(param::kCurrentWorkSystem, 1);
    return config;
}

double peakRssMb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_maxrss) / 1024.0;
}

void previewOf(benchmark::State& state, std::size_t lines) {
    const std::string path = program(lines).path();
    std::size_t bytes = 0, moves = 0;
    double coarsened = 0.0;
    for (auto _ : state) {
        preview::Preview p = preview::buildPreview(machine(), path);
        if (!p.loaded || p.alarm) {
            state.SkipWithError(p.alarm ? p.alarm->message.c_str() : "the program did not load");
            return;
        }
        bytes = p.bytes();
        moves = p.path.size();
        coarsened = p.coarsenedTo;
        benchmark::DoNotOptimize(p.path.bounds());
    }
    state.counters["moves"] = double(moves);
    state.counters["bytes_per_move"] = moves ? double(bytes) / double(moves) : 0.0;
    state.counters["peak_rss_mb"] = peakRssMb();
    state.counters["coarsened_to_mm"] = coarsened;
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * lines));
}

void BM_Preview_1M(benchmark::State& state) { previewOf(state, 1'000'000); }
BENCHMARK(BM_Preview_1M)->Unit(benchmark::kMillisecond);

void BM_Preview_10M(benchmark::State& state) { previewOf(state, 10'000'000); }
BENCHMARK(BM_Preview_10M)->Unit(benchmark::kMillisecond)->Iterations(1);

// 32,000,000 lines, about 1.1 GB: past the 12-million-move budget, so the path is coarsened
// (counter coarsened_to_mm) and memory stays bounded (run it alone: --benchmark_filter=Preview_1GB).
void BM_Preview_1GB(benchmark::State& state) { previewOf(state, 32'000'000); }
BENCHMARK(BM_Preview_1GB)->Unit(benchmark::kMillisecond)->Iterations(1);

// What a frame walks: the coarsest level fine enough for the scale, the chunks whose box meets the
// view, their points. At 1000 pixels for the whole path, then for a tenth of it.
void BM_LevelFrame_1M(benchmark::State& state) {
    static const preview::Preview p = preview::buildPreview(machine(), program(1'000'000).path());
    const preview::Box all = p.path.bounds();
    const double fraction = state.range(0) == 0 ? 1.0 : 0.1;
    const float width = (all.max.x - all.min.x) * float(fraction);
    const float height = (all.max.y - all.min.y) * float(fraction);
    const double mmPerPixel = std::max(width, height) / 1000.0;
    std::size_t drawn = 0;
    for (auto _ : state) {
        drawn = 0;
        auto visible = [&](const preview::Box& b) {
            return b.max.x >= all.min.x && b.min.x <= all.min.x + width && b.max.y >= all.min.y &&
                   b.min.y <= all.min.y + height;
        };
        if (const auto* level = p.levels.forScale(mmPerPixel)) {
            for (const auto& chunk : level->chunks) {
                if (visible(chunk.box)) {
                    for (const auto& point : chunk.points) {
                        benchmark::DoNotOptimize(point.at.x);
                        ++drawn;
                    }
                }
            }
        } else {
            for (const auto& chunk : p.path.chunks()) {
                if (visible(chunk.box)) {
                    for (const auto& s : chunk.segments) {
                        benchmark::DoNotOptimize(s.end.x);
                        ++drawn;
                    }
                }
            }
        }
    }
    state.counters["points"] = double(drawn);
}
BENCHMARK(BM_LevelFrame_1M)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

} // namespace
