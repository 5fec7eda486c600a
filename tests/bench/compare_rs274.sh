#!/usr/bin/env bash
# Compares m350-sim with LinuxCNC's standalone interpreter rs274 on the same machine, in the same
# run, on these workloads (the issue's performance targets; a benchmark, not a test):
#   g1         200,000 lines `G1 X.. Y.. Z.. F1000` (parse + execute), FANUC dialect      >= 20x rs274
#   g1-m350    the same lines on the default M350 machine (its tool rack checks every move)  >= 20x
#   g1-random  random X Y Z in +-100 mm, F on every line, default M350 machine              >= 20x
#   g1-nof     the same random moves with F only on the first line                          >= 20x
#   g1-seq     sequential coordinates (a 0.05 mm raster), default M350 machine              >= 20x
#   g1-n       the g1 lines numbered N10, N20, ... (as CAM output is), default M350 machine  >= 20x
#   loop       a 200,000-iteration WHILE loop with arithmetic, SIN and SQRT                 >= 20x
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
# g1_lines KIND END: the G1 program of a kind; the .ngc and .nc files differ only in the program
# end (M2 / M30). `g1` is the same as tests/bench/InterpreterBench.cpp. awk's srand(1) makes the
# random workloads the same in both files.
g1_lines() {
    awk -v n="$lines" -v kind="$1" -v end="$2" 'BEGIN {
        srand(1)
        for (i = 0; i < n; i++) {
            if (kind == "g1") {
                printf "G1 X%d.123 Y%d.456 Z-%d.789 F1000\n", i % 100, (i * 7) % 100, i % 10
            } else if (kind == "n") {
                printf "N%d G1 X%d.123 Y%d.456 Z-%d.789 F1000\n", (i + 1) * 10, i % 100, (i * 7) % 100, i % 10
            } else if (kind == "seq") {
                printf "G1 X%.3f Y%.3f Z-1.000 F1000\n", (i % 2000) * 0.05 - 50, int(i / 2000) * 0.05 - 50
            } else {
                x = rand() * 200 - 100; y = rand() * 200 - 100; z = rand() * 200 - 100
                printf "G1 X%.3f Y%.3f Z%.3f%s\n", x, y, z, (kind == "nof" && i > 0) ? "" : " F1000"
            }
        }
        print end
    }'
}
g1_kinds=(g1 n random nof seq)
for kind in "${g1_kinds[@]}"; do
    g1_lines "$kind" M2 > "$work/$kind.ngc"
    g1_lines "$kind" M30 > "$work/$kind.nc"
done

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

sim_loop=("$sim" run "$work/loop.nc" --dialect fanuc --max-sim-time 1000000000)
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

# sim_command WORKLOAD: the m350-sim command line of a G1 workload (into the array `cmd`)
sim_command() {
    case $1 in
        g1) cmd=("$sim" run "$work/g1.nc" --dialect fanuc --max-sim-time 1000000000) ;;
        g1-m350) cmd=("$sim" run "$work/g1.nc" --max-sim-time 1000000000) ;;
        g1-*) cmd=("$sim" run "$work/${1#g1-}.nc" --max-sim-time 1000000000) ;;
    esac
}
g1_file() { [[ $1 == g1 || $1 == g1-m350 ]] && echo g1 || echo "${1#g1-}"; }
g1_workloads=(g1 g1-m350 g1-n g1-random g1-nof g1-seq)

for kind in "${g1_kinds[@]}"; do
    "$rs274" -g "$work/$kind.ngc" > "$work/rs-$kind.out" 2> "$work/rs-$kind.err" ||
        die "rs274 $kind.ngc exited $? ($(tail -n1 "$work/rs-$kind.err"))"
    feeds=$(grep -c 'STRAIGHT_FEED(' "$work/rs-$kind.out" || true)
    [[ "$feeds" == "$lines" ]] || die "rs274 made $feeds STRAIGHT_FEED calls for $lines G1 lines of $kind.ngc"
done
for workload in "${g1_workloads[@]}"; do
    sim_command "$workload"
    file=$(g1_file "$workload")
    status=0
    "${cmd[@]}" > "$work/sim-$workload.json" 2> "$work/sim-$workload.err" || status=$?
    [[ $status -eq 0 ]] || die "m350-sim $workload exited $status: $(head -c 400 "$work/sim-$workload.err")"
    last_line=$(tail -n2 "$work/$file.nc" | head -n1)
    for axis in X Y Z; do
        want=$(sed -n "s/.*$axis\(-\{0,1\}[0-9.]*\).*/\1/p" <<< "$last_line")
        got=$(json_number "$work/sim-$workload.json" work "$axis")
        close "$got" "$want" 1e-6 || die "m350-sim $workload ended at $axis=$got, its last line says $want"
    done
done

"${rs_loop[@]}" > "$work/rs-loop.out" 2> "$work/rs-loop.err" || die "rs274 loop.ngc exited $? ($(tail -n1 "$work/rs-loop.err"))"
rs_result=$(sed -n 's/.*MESSAGE(" *\([-0-9.eE+]*\)").*/\1/p' "$work/rs-loop.out" | tail -n1)
[[ -n "$rs_result" ]] || die "rs274 loop.ngc printed no result (the debug MESSAGE is missing)"

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

declare -A rs_ns sim_ns
for kind in "${g1_kinds[@]}"; do
    rs_ns[$kind]=$(best_of "$rs274" -g "$work/$kind.ngc")
done
for workload in "${g1_workloads[@]}"; do
    sim_command "$workload"
    sim_ns[$workload]=$(best_of "${cmd[@]}")
done
rs_loop_ns=$(best_of "${rs_loop[@]}")
sim_loop_ns=$(best_of "${sim_loop[@]}")

echo "m350-sim: $sim"
echo "rs274:    $rs274"
echo "best of $repeat runs each, wall time of the whole process, output to /dev/null"
echo "g1*: $lines lines G1 X Y Z [F] each (rs274: as many STRAIGHT_FEED calls); loop: $iterations iterations" \
     "(#2 = $sim_result in m350-sim, $rs_result in rs274)"
echo
row() { # workload rs_ns sim_ns
    awk -v w="$1" -v rs="$2" -v sim="$3" -v target="$target" 'BEGIN {
        ratio = sim > 0 ? rs / sim : 0
        verdict = ratio >= target ? "PASS" : "BELOW TARGET"
        printf "%-10s %12.3f %14.3f %9.1fx   %s (target %dx)\n", w, rs / 1e9, sim / 1e9, ratio, verdict, target
    }'
}
printf "%-10s %12s %14s %10s   %s\n" workload "rs274 s" "m350-sim s" ratio verdict
for workload in "${g1_workloads[@]}"; do
    row "$workload" "${rs_ns[$(g1_file "$workload")]}" "${sim_ns[$workload]}"
done
row loop "$rs_loop_ns" "$sim_loop_ns"
