#!/usr/bin/env bash
# Builds and tests M350 Studio: a Release build with all tests, then (unless
# M350_SKIP_SANITIZE=1) a Debug build of the core and CLI under ASan/UBSan.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

header() {
    printf '\n==== %s ====\n' "$*"
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
    header "Configure build-asan (Debug, ASan/UBSan)"
    cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DM350_SANITIZE=ON \
        -DM350_BUILD_UI=OFF -DM350_BUILD_BENCH=OFF -DM350_WERROR=ON

    header "Build build-asan"
    cmake --build build-asan -j2

    header "Test build-asan"
    ASAN_OPTIONS=detect_leaks=1 \
        UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
        QT_QPA_PLATFORM=offscreen \
        ctest --test-dir build-asan --output-on-failure -j2
else
    header "Sanitizer build skipped (M350_SKIP_SANITIZE=1)"
fi

header "All tests passed"
