#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace m350::sim {

// The bounds of --trace-limit and --dprnt-limit: the trace keeps its head on disk; DPRNT output is
// held in memory until the run ends.
inline constexpr std::uint64_t kMostTraceBytes = 1ull << 40;
inline constexpr std::uint64_t kMostExternalOutputBytes = 4ull << 30;

// An option that bounds what a run keeps (`--trace-limit 64K`, `--dprnt-limit 1M`): a byte count
// with an optional K, M or G suffix (powers of 1024), from 1 byte up to `most`. Anything else is a
// usage error that names the option and its range.
CLI::Option* addByteLimitOption(CLI::App& command, const std::string& name, std::uint64_t& bytes, std::uint64_t most,
                                const std::string& description);

} // namespace m350::sim
