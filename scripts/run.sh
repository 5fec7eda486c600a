#!/usr/bin/env bash
# Builds M350 Studio (Release) and starts the desktop panel, or, when there is
# no display or the panel is not built, runs the example program headless.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

BUILD_DIR=build-release
HMI="$BUILD_DIR/app/m350-hmi"
SIM="$BUILD_DIR/app/m350-sim"
EXAMPLE=resources/examples/manual-test-program.nc

bash scripts/deps.sh
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD_DIR" -j2

run_example() {
    if [[ ! -x "$SIM" ]]; then
        echo "run.sh: $SIM was not built; nothing to run." >&2
        exit 1
    fi
    if [[ ! -f "$EXAMPLE" ]]; then
        echo "run.sh: example program $EXAMPLE not found." >&2
        exit 1
    fi
    echo "Running: $SIM run $EXAMPLE"
    # The simulator prints its JSON result; its exit status becomes ours.
    exec "$SIM" run "$EXAMPLE"
}

if [[ ! -x "$HMI" ]]; then
    echo "The desktop panel ($HMI) is not built yet; running the headless simulator instead."
    run_example
fi

if [[ -n "${DISPLAY:-}" || -n "${WAYLAND_DISPLAY:-}" ]]; then
    exec "$HMI" "$@"
fi

cat <<MSG
No display available (neither \$DISPLAY nor \$WAYLAND_DISPLAY is set), so the desktop panel cannot open.
To run headless:
  $SIM run $EXAMPLE      # simulate a program, print the JSON result
  xvfb-run -a $HMI       # run the panel on a virtual X server
Running the simulator example now.
MSG
run_example
