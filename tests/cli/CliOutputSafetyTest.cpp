// Issue 13: nothing m350-sim writes is lost and no input is destroyed. `--trace prog.nc` emptied
// the program and exited 0; write errors (a full disk) were ignored; runs writing one trace file at
// once interleaved their lines.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <thread>

namespace m350::clitest {

namespace {

std::string readAll(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

} // namespace

TEST_F(CliTest, AnOutputNamingAnInputOfTheRunIsRefusedBeforeAnythingIsWritten) {
    fs::path machine = dir_ / "machine";
    fs::copy(fs::path(M350_MACHINES_DIR) / "m350-linear16", machine, fs::copy_options::recursive);
    write("prog.nc", kEndingProgram);
    const std::string library = readAll(machine / "slib-g.nc");
    const std::string params = readAll(machine / "params.toml");
    for (std::vector<std::string> args : {std::vector<std::string>{"--trace", "prog.nc"},
                                          {"--trace", "./machine/../prog.nc"},
                                          {"--trace", "machine/slib-g.nc"},
                                          {"--dprnt", "machine/params.toml"},
                                          {"--tools-out", "prog.nc"}}) {
        std::vector<std::string> command{"run", "prog.nc", "--config", "machine"};
        command.insert(command.end(), args.begin(), args.end());
        ProcessResult r = sim(command);
        EXPECT_EQ(r.exitStatus, kExitUsage) << args[0] << " " << args[1] << ": " << r.err;
        EXPECT_NE(r.err.find("of this run"), std::string::npos) << r.err;
        EXPECT_EQ(readAll(dir_ / "prog.nc"), kEndingProgram);
        EXPECT_EQ(readAll(machine / "slib-g.nc"), library);
        EXPECT_EQ(readAll(machine / "params.toml"), params);
    }
    fs::create_symlink("prog.nc", dir_ / "link.nc");
    ProcessResult linked = sim({"run", "prog.nc", "--trace", "link.nc"});
    EXPECT_EQ(linked.exitStatus, kExitUsage) << linked.err;
    EXPECT_EQ(readAll(dir_ / "prog.nc"), kEndingProgram);
}

TEST_F(CliTest, WriteErrorsAreAnErrorNotASuccess) {
    write("prog.nc", kEndingProgram);
    ProcessResult trace = sim({"run", "prog.nc", "--trace", "/dev/full"});
    EXPECT_EQ(trace.exitStatus, kExitError) << trace.err;
    EXPECT_NE(trace.err.find("--trace: /dev/full: cannot write: No space left on device"), std::string::npos)
        << trace.err;
    json j = output(trace);
    EXPECT_EQ(j.value("status", ""), "error");
    EXPECT_EQ(j["alarm"].value("code", ""), "file_error") << j;

    // stdout on a full disk, for run and check alike
    for (const char* command : {"run", "check"}) {
        pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            ::freopen("/dev/full", "w", stdout);
            ::freopen("/dev/null", "w", stderr);
            ::chdir(dir_.c_str());
            ::execl(M350_SIM_PATH, M350_SIM_PATH, command, "prog.nc", static_cast<char*>(nullptr));
            ::_exit(127);
        }
        int status = 0;
        ASSERT_EQ(::waitpid(child, &status, 0), child);
        ASSERT_TRUE(WIFEXITED(status));
        EXPECT_EQ(WEXITSTATUS(status), kExitError) << command;
    }

    ProcessResult devNull = sim({"run", "prog.nc", "--trace", "/dev/null"});
    EXPECT_EQ(devNull.exitStatus, kExitOk) << devNull.err << " (a device is written, not replaced)";
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

// Each run writes the trace beside it and renames it over the target: the file is always one whole
// run's trace, and no temp file is left behind.
TEST_F(CliTest, ConcurrentRunsWritingOneTraceLeaveOneWholeTrace) {
    write("prog.nc", "#1=0\nWHILE[#1 LT #2] DO1\nG1 X[#1/10+#3] F3000\n#1=#1+1\nEND1\nM30\n");
    constexpr int kRuns = 8;
    // each run's trace differs in length and in every line
    auto varsOf = [](int run) { return std::vector<std::string>{"--var", "2=" + std::to_string(1000 + 300 * run), "--var",
                                                                "3=" + std::to_string(run)}; };
    auto command = [&](int run, const std::string& trace) {
        std::vector<std::string> args{"run", "prog.nc", "--trace", trace};
        std::vector<std::string> vars = varsOf(run);
        args.insert(args.end(), vars.begin(), vars.end());
        return args;
    };
    std::set<std::string> wholeTraces;
    for (int run = 0; run < kRuns; ++run) {
        const std::string file = "alone" + std::to_string(run) + ".jsonl";
        ProcessResult alone = sim(command(run, file));
        ASSERT_EQ(alone.exitStatus, kExitOk) << alone.err;
        wholeTraces.insert(readAll(dir_ / file));
    }
    ASSERT_EQ(wholeTraces.size(), static_cast<std::size_t>(kRuns));

    std::vector<std::thread> runs;
    std::vector<int> statuses(kRuns, -1);
    for (int run = 0; run < kRuns; ++run) {
        runs.emplace_back([&, run] {
            statuses[static_cast<std::size_t>(run)] =
                sim(command(run, "shared.jsonl")).exitStatus;
        });
    }
    for (std::thread& run : runs) {
        run.join();
    }
    for (int status : statuses) {
        EXPECT_EQ(status, kExitOk);
    }
    EXPECT_EQ(wholeTraces.count(readAll(dir_ / "shared.jsonl")), 1u) << "the trace is not one run's whole trace";
    for (const fs::directory_entry& entry : fs::directory_iterator(dir_)) {
        EXPECT_NE(entry.path().filename().string().rfind(".shared.jsonl", 0), 0u) << entry.path() << " left behind";
    }
}

} // namespace m350::clitest
