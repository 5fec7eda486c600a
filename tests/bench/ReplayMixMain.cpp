// Writes a long replay of real operator actions (tests/bench/ReplayMix.h) for tests/bench/replay_1m.sh.
// Usage: m350-replay-mix COUNT FOLDER: FOLDER/mix.jsonl and FOLDER/part.nc (the program it runs).
#include "tests/bench/ReplayMix.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

int main(int argc, char** argv) {
    if (argc != 3 || std::atol(argv[1]) <= 0) {
        std::fprintf(stderr, "usage: m350-replay-mix COUNT FOLDER\n");
        return 64;
    }
    const std::filesystem::path folder = std::filesystem::absolute(argv[2]);
    std::ofstream program(folder / "part.nc");
    program << m350::test::ReplayMix::programText();
    std::ofstream replay(folder / "mix.jsonl");
    m350::test::ReplayMix mix(1, (folder / "part.nc").string());
    mix.write(std::atol(argv[1]), [&replay](const std::string& line) { replay << line << '\n'; });
    program.close();
    replay.close();
    if (!program || !replay) {
        std::fprintf(stderr, "m350-replay-mix: cannot write into %s\n", folder.c_str());
        return 1;
    }
    return 0;
}
