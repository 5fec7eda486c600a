#!/usr/bin/env bash
# Runs each libFuzzer target of the sanitizer build (build-asan, which scripts/test.sh configures
# with -DM350_FUZZ=ON; M350_FUZZ_BUILD names another) for SECONDS from its seeds in
# tests/fuzz/corpus/<target>/ and prints the executions. New inputs go to BUILD/corpus/<target>/
# (the seeds are not touched); a crash, leak, UB report or an input running over 5 s is saved in
# BUILD/findings/ and fails the run. The targets run side by
# side, as many at once as the machine has cores (M350_FUZZ_JOBS sets it), each for SECONDS.
# Usage: scripts/fuzz.sh [SECONDS] [TARGET...]   (targets: parser evaluator machine-folder)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

seconds=${1:-60}
shift || true
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(parser evaluator machine-folder)

build=${M350_FUZZ_BUILD:-build-asan}
mkdir -p "$build/findings"
jobs=${M350_FUZZ_JOBS:-$(nproc)}

fuzz() { # TARGET: runs it, its exit status in $build/findings/TARGET.status
    local target=$1 status=0
    local fuzzer=$build/tests/fuzz/m350-fuzz-$target
    local dictionary=(-dict=tests/fuzz/gcode.dict)
    [[ "$target" != machine-folder ]] || dictionary=(-dict=tests/fuzz/toml.dict)
    mkdir -p "$build/corpus/$target"
    UBSAN_OPTIONS=print_stacktrace=1 "$fuzzer" "${dictionary[@]}" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=2048 \
        -print_final_stats=1 -artifact_prefix="$build/findings/$target-" \
        "$build/corpus/$target" "tests/fuzz/corpus/$target" > "$build/findings/$target.log" 2>&1 || status=$?
    echo "$status" > "$build/findings/$target.status"
}

running=0
for target in "${targets[@]}"; do
    if ((running >= jobs)); then
        wait -n
        running=$((running - 1))
    fi
    rm -f "$build/findings/$target.status"
    fuzz "$target" &
    running=$((running + 1))
done
wait

failed=0
for target in "${targets[@]}"; do
    log=$build/findings/$target.log
    status=$(cat "$build/findings/$target.status" 2>/dev/null || echo "?")
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
    if [[ "$status" == 0 ]]; then
        echo "fuzz $target: ${runs:-?} executions in $seconds s (${speed:-?}/s), no finding"
    else
        echo "fuzz $target: FAILED (exit $status) after ${runs:-?} executions; log $log:"
        grep -E '^(==[0-9]+==ERROR|SUMMARY|artifact_prefix|Test unit written|.*runtime error)' "$log" | head -20
        failed=1
    fi
done
exit $failed
