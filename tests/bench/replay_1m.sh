#!/usr/bin/env bash
# How long m350-hmi takes to play a long replay of real operator actions headless (tests/bench/
# ReplayMix.h: page switches among all the pages, softkeys, jog taps in STEP mode, override keys,
# wheel clicks, MDI lines typed and run, a program run twice), wall and CPU seconds, played fast
# (as every replay plays) and, with --eager, the way m350-hmi played replays before (--eager-replay).
# It measures; it never fails on speed.
# Usage: tests/bench/replay_1m.sh [--eager] [BUILD_DIR] [ACTIONS]   (default build, 1000000)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
eager=()
if [[ "${1:-}" == "--eager" ]]; then
    eager=(--eager-replay)
    shift
fi
BUILD=${1:-build}
ACTIONS=${2:-1000000}
HMI="$BUILD/app/m350-hmi"
MIX="$BUILD/tests/bench/m350-replay-mix"
for program in "$HMI" "$MIX"; do
    [[ -x "$program" ]] || { echo "replay_1m.sh: $program is not built" >&2; exit 1; }
done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$MIX" "$ACTIONS" "$work"
echo "replay: $ACTIONS actions, $(wc -l < "$work/mix.jsonl") lines, $(tail -1 "$work/mix.jsonl" | sed 's/.*"t":\([0-9.]*\).*/\1/') s of virtual time"
start=$(date +%s.%N)
QT_QPA_PLATFORM=offscreen /usr/bin/time -f "%U %S %M" -o "$work/time" "$HMI" "${eager[@]}" --replay "$work/mix.jsonl" \
    --programs "$work" --state "$work/state.json" --screenshot "$work/screen.png" 2>"$work/errors" || {
    cat "$work/errors" >&2
    exit 1
}
end=$(date +%s.%N)
read -r user system memory < "$work/time"
awk -v w="$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')" -v u="$user" -v s="$system" -v m="$memory" -v mode="${eager[*]:-fast}" \
    'BEGIN { printf "%s: %.1f s wall, %.1f s CPU (%.1f user + %.1f system), %.0f MB at most\n", mode, w, u + s, u, s, m / 1024 }'
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
