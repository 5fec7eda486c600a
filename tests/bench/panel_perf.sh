#!/usr/bin/env bash
# The panel's own figures, as an operator would feel them: under Xvfb, while a long program runs
# in real time, how often the screen repaints, how much of one core the process uses, how long a
# snapshot takes from the machine thread to a painted screen, and how long start-up takes to the
# first painted window. Usage: tests/bench/panel_perf.sh [BUILD_DIR] [SECONDS] [PAGE]
# (PAGE: the page shown, monitor by default; graphics measures the machine view's repaints)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
BUILD=${1:-build}
SECONDS_TO_RUN=${2:-10}
PAGE=${3:-monitor}
HMI="$BUILD/app/m350-hmi"
[[ -x "$HMI" ]] || { echo "panel_perf.sh: $HMI is not built" >&2; exit 1; }
command -v xvfb-run >/dev/null || { echo "panel_perf.sh: xvfb-run is missing (apt-get install xvfb)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# A long program: a zig-zag over the table at 3000 mm/min, far longer than the measurement.
{
    echo "G90 G54 G0 X0 Y0"
    for i in $(seq 1 4000); do
        echo "G1 X$(( (i % 2) * 200 )) Y$(( i % 100 )) F3000"
    done
    echo "M30"
} > "$work/long.nc"

for run in 1 2 3; do
    xvfb-run -a -s "-screen 0 1280x800x24" "$HMI" --lang zh_CN --page "$PAGE" --measure "$SECONDS_TO_RUN" "$work/long.nc" 2>/dev/null
done
