#!/usr/bin/env bash
# Builds and tests M350 Studio: a Release build with all tests, then (unless
# M350_SKIP_SANITIZE=1) a clang Debug build of the core, the CLI and their tests under ASan/UBSan
# (clang compiles it in about half GCC's time) with, unless M350_SKIP_FUZZ=1, the libFuzzer targets
# of tests/fuzz, each run for M350_FUZZ_SECONDS (default 30) from its seed corpus once the tests
# pass. A crash, leak, UB or an input that runs over 5 s fails the step; the input is kept in
# build-asan/findings/.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

# each stage says when it starts (seconds since this script began): where CI's time goes
header() {
    printf '\n==== %s ==== (%d s)\n' "$*" "$SECONDS"
}

header "Dependencies"
bash scripts/deps.sh

header "Configure build (Release)"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DM350_WERROR=ON

header "Build build (Release)"
cmake --build build -j2

header "Test build (Release)"
QT_QPA_PLATFORM=offscreen ctest --test-dir build --output-on-failure -j2

if [[ "${M350_SKIP_SANITIZE:-0}" != "1" ]]; then
    fuzz=ON
    [[ "${M350_SKIP_FUZZ:-0}" != "1" ]] || fuzz=OFF
    header "Configure build-asan (clang, Debug, ASan/UBSan, fuzz targets $fuzz)"
    cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++ -DM350_SANITIZE=ON \
        -DM350_FUZZ=$fuzz -DM350_BUILD_UI=OFF -DM350_BUILD_BENCH=OFF -DM350_WERROR=ON

    header "Build build-asan"
    cmake --build build-asan -j2

    header "Test build-asan"
    ASAN_OPTIONS=detect_leaks=1 \
        UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
        QT_QPA_PLATFORM=offscreen \
        ctest --test-dir build-asan --output-on-failure -j2

    if [[ "$fuzz" == ON ]]; then
        header "Fuzz (${M350_FUZZ_SECONDS:-30} s per target)"
        bash scripts/fuzz.sh "${M350_FUZZ_SECONDS:-30}"
    else
        header "Fuzzing skipped (M350_SKIP_FUZZ=1)"
    fi
else
    header "Sanitizer build and fuzzing skipped (M350_SKIP_SANITIZE=1)"
fi

header "All tests passed"
