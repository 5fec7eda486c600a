// Differential tests against LinuxCNC (see README.md here). Each program under programs/ is one test
// case: m350-sim runs it in the FANUC dialect on the bundled fanuc-0i mill, LinuxCNC's standalone
// interpreter rs274 runs the same text (or NAME.ngc beside it when the spelling must differ), and
// both must move through the same machine positions:
//   - move by move: kind (rapid / feed / arc) and end point X Y Z, m350-sim's --trace against
//     rs274's STRAIGHT_TRAVERSE / STRAIGHT_FEED / ARC_FEED turned into machine coordinates
//     (Rs274Canon.h says how);
//   - arcs also by path length, which tells the short way from the long one and G2 from G3 (but
//     for half circles): rs274's from the ARC_FEED centre and turns, m350-sim's from the trace as
//     feed x duration. So that the duration is exactly length / feed, m350-sim runs with a feed
//     acceleration (parameter 62) so high that its exact-stop ramps take no measurable time;
//   - the final machine position of m350-sim's report against rs274's last end point.
// Positions agree within 1e-4 mm (rs274 prints 4 decimals, so the programs use at most 4), arc
// lengths within 1e-3 mm (rs274's centres are rounded to 4 decimals too).
// Cutter compensation (G41/G42) is left out until m350-sim applies it.
// Without rs274 (Debian package linuxcnc-uspace) every case is skipped with the reason.
#include "tests/cli/SimProcess.h"
#include "tests/diff/Rs274Canon.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using m350::testing::CanonMove;
using m350::testing::CanonRun;
using m350::testing::Point;
using nlohmann::json;

constexpr double kTolerance = 1e-4;          // mm
constexpr double kArcLengthTolerance = 1e-3; // mm
// Parameter 62, G01 acceleration in mm/s^2: high enough that a move takes length / feed.
constexpr const char* kInstantAcceleration = "62=1e9";

fs::path programDirectory() {
    return fs::path(M350_DIFF_PROGRAM_DIR);
}

// The cases: programs/NAME.nc, by NAME.
std::vector<std::string> programNames() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const fs::directory_entry& entry : fs::directory_iterator(programDirectory(), ec)) {
        if (entry.is_regular_file() && entry.path().extension() == ".nc") {
            names.push_back(entry.path().stem().string());
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

// $RS274 when set (as tests/bench/compare_rs274.sh reads it), else the first rs274 on PATH. When there
// is none, `why` says what was looked at.
std::optional<fs::path> findRs274(std::string& why) {
    if (const char* given = std::getenv("RS274"); given != nullptr && *given != '\0') {
        if (::access(given, X_OK) == 0) {
            return fs::absolute(given); // rs274 runs in another directory
        }
        why = std::string("RS274=") + given + " is not an executable file";
        return std::nullopt;
    }
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path != nullptr ? path : "/usr/local/bin:/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        fs::path candidate = fs::path(dir.empty() ? "." : dir) / "rs274";
        if (::access(candidate.c_str(), X_OK) == 0) {
            return fs::absolute(candidate);
        }
    }
    why = "no rs274 on PATH; set RS274 to use one elsewhere";
    return std::nullopt;
}

// A fresh directory for one case's files, removed with everything in it afterwards.
class ScratchDirectory {
  public:
    ScratchDirectory() {
        std::string pattern = (fs::temp_directory_path() / "m350-diff.XXXXXX").string();
        if (::mkdtemp(pattern.data()) == nullptr) {
            throw std::runtime_error("mkdtemp failed for " + pattern);
        }
        path_ = pattern;
    }
    ~ScratchDirectory() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    ScratchDirectory(const ScratchDirectory&) = delete;
    ScratchDirectory& operator=(const ScratchDirectory&) = delete;
    const fs::path& path() const { return path_; }

  private:
    fs::path path_;
};

struct SimMove {
    std::string kind;
    Point machine{};
    double arcLength = 0.0; // arcs: feed x duration
    int line = 0;
};

struct SimRun {
    std::vector<SimMove> moves;
    Point final{};
    std::string failure; // empty when the run finished with status "ok"
};

struct LinuxCncRun {
    CanonRun canon;
    std::string failure;
};

Point axesOf(const json& axes) {
    return {axes.at("X").get<double>(), axes.at("Y").get<double>(), axes.at("Z").get<double>()};
}

SimRun runSim(const fs::path& program, const fs::path& scratch) {
    const fs::path trace = scratch / "trace.jsonl";
    std::vector<std::string> args{"run",     program.string(), "--dialect", "fanuc",
                                  "--trace", trace.string(),   "--param",   kInstantAcceleration};
    // NAME.sim.tbl: m350-sim's tool table, for a case whose program writes the table itself
    if (const fs::path table = fs::path(program).replace_extension(".sim.tbl"); fs::exists(table)) {
        args.insert(args.end(), {"--tool-table", table.string()});
    }
    const m350::testing::ProcessResult result =
        m350::testing::runProcess(M350_SIM_PATH, args, scratch.string());
    SimRun run;
    try {
        const json report = json::parse(result.out);
        if (result.exitStatus != 0 || report.value("status", "") != "ok") {
            run.failure = "m350-sim did not finish the program (exit " + std::to_string(result.exitStatus) +
                          "):\n" + result.out + "\n" + result.err;
            return run;
        }
        run.final = axesOf(report.at("machine"));
        std::ifstream in(trace);
        std::string line;
        while (std::getline(in, line)) {
            const json event = json::parse(line);
            if (event.value("type", "") != "move") {
                continue;
            }
            SimMove move{event.at("kind").get<std::string>(), axesOf(event.at("to")), 0.0,
                         event.value("line", 0)};
            if (move.kind == "arc") {
                move.arcLength = event.at("feed").get<double>() / 60.0 *
                                 (event.at("end").get<double>() - event.at("start").get<double>());
            }
            run.moves.push_back(move);
        }
    } catch (const json::exception& e) {
        run.failure =
            std::string("unreadable m350-sim output (") + e.what() + "):\n" + result.out + "\n" + result.err;
    }
    return run;
}

// rs274 runs in the scratch directory, so no rs274ngc.var from elsewhere is read, with HOME there too:
// it keeps the tool table in $HOME/.tool.mmap, which rs274 runs in parallel (ctest -j) would share
// and corrupt (SIGBUS, or the tools of another case). It always gets a tool table: the program's
// NAME.tbl, or an empty one rather than the sample table rs274 falls back on. The program's NAME.var,
// when there is one, is read from a copy: rs274 writes the file back.
LinuxCncRun runRs274(const fs::path& rs274, const fs::path& program, const fs::path& scratch) {
    fs::path table = fs::path(program).replace_extension(".tbl");
    if (!fs::exists(table)) {
        table = scratch / "empty.tbl";
        std::ofstream(table).flush();
    }
    std::vector<std::string> args{"HOME=" + scratch.string(), rs274.string(), "-g", "-t", table.string()};
    if (const fs::path parameters = fs::path(program).replace_extension(".var"); fs::exists(parameters)) {
        const fs::path copy = scratch / "parameters.var";
        fs::copy_file(parameters, copy);
        args.insert(args.end(), {"-v", copy.string()});
    }
    args.push_back(program.string());
    const m350::testing::ProcessResult result =
        m350::testing::runProcess("/usr/bin/env", args, scratch.string());
    LinuxCncRun run;
    if (result.exitStatus != 0) {
        run.failure = "rs274 stopped with exit " + std::to_string(result.exitStatus) + ":\n" + result.err;
        return run;
    }
    run.canon = m350::testing::readCanonOutput(result.out);
    if (!run.canon.programEnded) {
        run.failure =
            "rs274 never reached PROGRAM_END (end the program with M2):\n" + result.out + result.err;
    }
    return run;
}

bool near(const Point& a, const Point& b) {
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!(std::abs(a[i] - b[i]) <= kTolerance)) {
            return false;
        }
    }
    return true;
}

std::string fixed4(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4f", v);
    return buffer;
}

std::string formatted(const Point& p) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "X%.4f Y%.4f Z%.4f", p[0], p[1], p[2]);
    return buffer;
}

std::string trimmed(const std::string& s) {
    const std::size_t first = s.find_first_not_of(" \t");
    return first == std::string::npos ? std::string() : s.substr(first);
}

// Both move lists side by side, the rows that disagree marked; `differing` counts them.
std::string moveTable(const std::vector<SimMove>& sim, const std::vector<CanonMove>& canon, int& differing) {
    std::ostringstream table;
    differing = 0;
    const std::size_t rows = std::max(sim.size(), canon.size());
    for (std::size_t i = 0; i < rows; ++i) {
        const SimMove* s = i < sim.size() ? &sim[i] : nullptr;
        const CanonMove* c = i < canon.size() ? &canon[i] : nullptr;
        const bool same = s && c && s->kind == c->kind && near(s->machine, c->machine) &&
                          std::abs(s->arcLength - c->arcLength) <= kArcLengthTolerance;
        differing += same ? 0 : 1;
        table << (same ? "   " : "!! ") << "move " << i + 1 << "\n     m350-sim: ";
        if (s) {
            table << "line " << s->line << " " << s->kind << " to " << formatted(s->machine)
                  << (s->kind == "arc" ? ", length " + fixed4(s->arcLength) : "");
        } else {
            table << "(none)";
        }
        table << "\n     rs274:    ";
        if (c) {
            table << c->kind << " to " << formatted(c->machine)
                  << (c->kind == "arc" ? ", length " + fixed4(c->arcLength) : "") << "   ["
                  << trimmed(c->call) << "]";
        } else {
            table << "(none)";
        }
        table << "\n";
    }
    return table.str();
}

class DifferentialTest : public ::testing::TestWithParam<std::string> {};

TEST_P(DifferentialTest, MachinePositionsMatchLinuxCnc) {
    std::string why;
    const std::optional<fs::path> rs274 = findRs274(why);
    if (!rs274) {
        GTEST_SKIP() << "rs274 (linuxcnc-uspace) not installed: " << why;
    }
    const fs::path program = programDirectory() / (GetParam() + ".nc");
    fs::path linuxCncProgram = fs::path(program).replace_extension(".ngc");
    if (!fs::exists(linuxCncProgram)) {
        linuxCncProgram = program;
    }
    ScratchDirectory scratch;

    const SimRun sim = runSim(program, scratch.path());
    ASSERT_TRUE(sim.failure.empty()) << program.string() << "\n" << sim.failure;
    const LinuxCncRun linuxCnc = runRs274(*rs274, linuxCncProgram, scratch.path());
    ASSERT_TRUE(linuxCnc.failure.empty()) << linuxCncProgram.string() << "\n" << linuxCnc.failure;
    for (const std::string& problem : linuxCnc.canon.problems) {
        ADD_FAILURE() << linuxCncProgram.string() << ": " << problem;
    }

    const std::vector<CanonMove>& canon = linuxCnc.canon.moves;
    const Point linuxCncFinal = canon.empty() ? Point{} : canon.back().machine;
    int differing = 0;
    const std::string table = moveTable(sim.moves, canon, differing);
    EXPECT_TRUE(near(sim.final, linuxCncFinal)) << "final machine position: m350-sim " << formatted(sim.final)
                                                << ", rs274 " << formatted(linuxCncFinal);
    EXPECT_EQ(differing, 0) << differing << " of the moves differ (m350-sim " << sim.moves.size()
                            << " moves, rs274 " << canon.size() << "); program " << program.string() << "\n"
                            << table;
}

INSTANTIATE_TEST_SUITE_P(Programs, DifferentialTest, ::testing::ValuesIn(programNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return m350::testing::testNameFor(info.param);
                         });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(DifferentialTest);

} // namespace
