#!/usr/bin/env bash
# Compares m350-sim with LinuxCNC's standalone interpreter rs274 on the same machine, in the same
# run, on two workloads (the issue's performance targets; a benchmark, not a test):
#   g1    200,000 lines `G1 X.. Y.. Z.. F1000` (parse + execute)            target: >= 20x rs274
#   loop  a 200,000-iteration WHILE loop with arithmetic, SIN and SQRT      target: >= 20x rs274
# Each program is first run once untimed to prove it really executes (rs274's canonical calls are
# counted; m350-sim must exit 0 and end where the program says), then timed best of 5 as whole
# processes (start-up included, output to /dev/null).
#
# Usage: tests/bench/compare_rs274.sh [path/to/m350-sim]     (default: build/app/m350-sim)
# Environment: RS274 (default: rs274 on PATH), M350_BENCH_LINES, M350_BENCH_ITERATIONS,
#              M350_BENCH_REPEAT (default 5).
# Exit status: 0 when the comparison ran (whatever the ratios) or rs274 is not installed;
#              1 when a program did not run correctly; 2 on a usage or set-up problem.
set -euo pipefail

script_dir=$(cd -- "$(dirname -- "${BASH_SOURCE[0]}")" && pwd)
repo_root=$(cd -- "$script_dir/../.." && pwd)

sim=${1:-$repo_root/build/app/m350-sim}
lines=${M350_BENCH_LINES:-200000}
iterations=${M350_BENCH_ITERATIONS:-200000}
repeat=${M350_BENCH_REPEAT:-5}
target=20

rs274=${RS274:-$(command -v rs274 || true)}
if [[ -z "$rs274" || ! -x "$rs274" ]]; then
    echo "compare_rs274: SKIPPED: LinuxCNC's standalone interpreter rs274 is not installed" \
         "(Debian: linuxcnc-uspace; or set RS274=/path/to/rs274). Nothing was measured."
    exit 0
fi
if [[ ! -x "$sim" ]]; then
    echo "compare_rs274: m350-sim not found or not executable: $sim" >&2
    echo "  build it (cmake --build build --target m350-sim) or pass its path as the first argument" >&2
    exit 2
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/m350-rs274.XXXXXX")
trap 'rm -rf -- "$work"' EXIT

die() {
    echo "compare_rs274: FAILED: $*" >&2
    exit 1
}

# --- the workloads, one generator per language ------------------------------------------------
# Same G1 lines as tests/bench/InterpreterBench.cpp; only the program end differs (M2 / M30).
g1_lines() {
    awk -v n="$lines" -v end="$1" 'BEGIN {
        for (i = 0; i < n; i++)
            printf "G1 X%d.123 Y%d.456 Z-%d.789 F1000\n", i % 100, (i * 7) % 100, i % 10
        print end
    }'
}
g1_lines M2 > "$work/g1.ngc"
g1_lines M30 > "$work/g1.nc"

cat > "$work/loop.ngc" <<EOF
#1 = 0
#2 = 0
o100 while [#1 LT $iterations]
#2 = [SIN[#1] * SQRT[#1] + #2/2]
#1 = [#1 + 1]
o100 endwhile
(debug, #2)
M2
EOF

cat > "$work/loop.nc" <<EOF
#1=0
#2=0
WHILE [#1 LT $iterations] DO1
#2=SIN[#1]*SQRT[#1]+#2/2
#1=#1+1
END1
M30
EOF

sim_g1=("$sim" run "$work/g1.nc" --dialect fanuc --max-sim-time 1000000000)
sim_loop=("$sim" run "$work/loop.nc" --dialect fanuc --max-sim-time 1000000000)
rs_g1=("$rs274" -g "$work/g1.ngc")
rs_loop=("$rs274" -g "$work/loop.ngc")

# --- prove each program really runs (untimed) -------------------------------------------------
# A number from m350-sim's JSON: json_number FILE SECTION KEY (e.g. work X, vars 2).
json_number() {
    grep -o "\"$2\":{[^}]*}" "$1" | grep -o "\"$3\":[-0-9.eE+]*" | head -n1 | cut -d: -f2
}
# close A B TOLERANCE
close() {
    awk -v a="$1" -v b="$2" -v tol="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a != "" && b != "" && d <= tol) }'
}

"${rs_g1[@]}" > "$work/rs-g1.out" 2> "$work/rs-g1.err" || die "rs274 g1.ngc exited $? ($(tail -n1 "$work/rs-g1.err"))"
feeds=$(grep -c 'STRAIGHT_FEED(' "$work/rs-g1.out" || true)
[[ "$feeds" == "$lines" ]] || die "rs274 made $feeds STRAIGHT_FEED calls for $lines G1 lines"

"${rs_loop[@]}" > "$work/rs-loop.out" 2> "$work/rs-loop.err" || die "rs274 loop.ngc exited $? ($(tail -n1 "$work/rs-loop.err"))"
rs_result=$(sed -n 's/.*MESSAGE(" *\([-0-9.eE+]*\)").*/\1/p' "$work/rs-loop.out" | tail -n1)
[[ -n "$rs_result" ]] || die "rs274 loop.ngc printed no result (the debug MESSAGE is missing)"

status=0
"${sim_g1[@]}" > "$work/sim-g1.json" 2> "$work/sim-g1.err" || status=$?
[[ $status -eq 0 ]] || die "m350-sim g1.nc exited $status: $(head -c 400 "$work/sim-g1.err")"
last=$((lines - 1))
declare -A want=([X]="$((last % 100)).123" [Y]="$(((last * 7) % 100)).456" [Z]="-$((last % 10)).789")
for axis in X Y Z; do
    got=$(json_number "$work/sim-g1.json" work "$axis")
    close "$got" "${want[$axis]}" 1e-6 || die "m350-sim g1.nc ended at $axis=$got, the last line says ${want[$axis]}"
done

status=0
"${sim_loop[@]}" --print 1,2 > "$work/sim-loop.json" 2> "$work/sim-loop.err" || status=$?
[[ $status -eq 0 ]] || die "m350-sim loop.nc exited $status: $(head -c 400 "$work/sim-loop.err")"
sim_count=$(json_number "$work/sim-loop.json" vars 1)
sim_result=$(json_number "$work/sim-loop.json" vars 2)
close "$sim_count" "$iterations" 0 || die "m350-sim loop.nc ended with #1=$sim_count, expected $iterations"
close "$sim_result" "$rs_result" 1e-5 || die "loop results differ: m350-sim #2=$sim_result, rs274 #2=$rs_result"

# --- timing -----------------------------------------------------------------------------------
# best_of COMMAND...: prints the fastest wall time of $repeat runs, in nanoseconds.
best_of() {
    local best="" start end elapsed rc
    for ((r = 0; r < repeat; r++)); do
        start=$(date +%s%N)
        rc=0
        "$@" > /dev/null 2>&1 || rc=$?
        end=$(date +%s%N)
        [[ $rc -eq 0 ]] || die "timed run exited $rc: $*"
        elapsed=$((end - start))
        if [[ -z "$best" || $elapsed -lt $best ]]; then best=$elapsed; fi
    done
    echo "$best"
}

rs_g1_ns=$(best_of "${rs_g1[@]}")
sim_g1_ns=$(best_of "${sim_g1[@]}")
rs_loop_ns=$(best_of "${rs_loop[@]}")
sim_loop_ns=$(best_of "${sim_loop[@]}")

echo "m350-sim: $sim"
echo "rs274:    $rs274"
echo "best of $repeat runs each, wall time of the whole process, output to /dev/null"
echo "g1: $lines lines G1 X Y Z F (rs274: $feeds STRAIGHT_FEED calls); loop: $iterations iterations" \
     "(#2 = $sim_result in m350-sim, $rs_result in rs274)"
echo
row() { # workload rs_ns sim_ns
    awk -v w="$1" -v rs="$2" -v sim="$3" -v target="$target" 'BEGIN {
        ratio = sim > 0 ? rs / sim : 0
        verdict = ratio >= target ? "PASS" : "BELOW TARGET"
        printf "%-8s %12.3f %14.3f %9.1fx   %s (target %dx)\n", w, rs / 1e9, sim / 1e9, ratio, verdict, target
    }'
}
printf "%-8s %12s %14s %10s   %s\n" workload "rs274 s" "m350-sim s" ratio verdict
row g1 "$rs_g1_ns" "$sim_g1_ns"
row loop "$rs_loop_ns" "$sim_loop_ns"
