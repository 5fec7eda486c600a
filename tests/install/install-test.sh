#!/usr/bin/env bash
# Installs the build as a user would and runs the programs from there, away from the source tree:
#  1. `cmake --install` into a scratch DESTDIR (prefix /usr);
#  2. `cpack -G DEB`, the package's contents and Depends checked with dpkg-deb, then unpacked into
#     a second scratch root (dpkg-deb -x: no root, no container).
# In each root: both programs' --version, a run of the bundled example on the bundled machine, a
# panel screenshot, and a proof that the installed share/m350-studio is the one read (an installed
# machine broken on purpose makes them fail, naming the installed file), and nothing written into it.
# Usage: install-test.sh BUILD_DIR ui|no-ui
set -euo pipefail

build=$1
ui=$2
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
export HOME=$scratch/home XDG_RUNTIME_DIR=$scratch/runtime QT_QPA_PLATFORM=offscreen
mkdir -p "$HOME" "$XDG_RUNTIME_DIR"
chmod 700 "$XDG_RUNTIME_DIR"

fail() {
    echo "install-test: $*" >&2
    exit 1
}

expect_file() {
    [[ -f "$1/$2" ]] || fail "$2 is not in $1"
}

tree_sum() {
    (cd "$1" && find . -type f -print0 | sort -z | xargs -0 sha256sum)
}

exercise() {
    local root=$1 label=$2
    local bin=$root/usr/bin share=$root/usr/share/m350-studio
    echo "-- $label: $root"
    for f in usr/bin/m350-sim usr/share/m350-studio/machines/m350-linear16/machine.toml \
             usr/share/m350-studio/machines/m350-linear16/T.nc usr/share/m350-studio/examples/manual-test-program.nc \
             usr/share/m350-studio/parameters/m350-parameters.tsv usr/share/man/man1/m350-sim.1 \
             usr/share/doc/m350-studio/README.md; do
        expect_file "$root" "$f"
    done
    grep -q '^\.SS m350-sim run$' "$root/usr/share/man/man1/m350-sim.1" || fail "m350-sim.1 lacks the run command's options"
    grep -qF '\-\-max\-sim\-time' "$root/usr/share/man/man1/m350-sim.1" || fail "m350-sim.1 lacks run's options"

    local version
    version=$("$bin/m350-sim" --version)
    [[ "$version" =~ ^m350-sim\ [0-9]+\.[0-9]+\.[0-9]+\ \(commit\ ([0-9a-f]{12}|unknown)\)$ ]] ||
        fail "m350-sim --version said '$version'"

    local before
    before=$(tree_sum "$share")
    # the bundled example on the bundled default machine: its T.nc changes tools 1, 2, 3
    local report
    report=$(cd "$scratch" && "$bin/m350-sim" run "$share/examples/manual-test-program.nc")
    grep -q '"status":"ok"' <<<"$report" || fail "m350-sim run: $report"
    grep -q '"tool":3' <<<"$report" || fail "m350-sim run did not end with tool 3: $report"
    report=$(cd "$scratch" && "$bin/m350-sim" run --config "$share/machines/m350-rack-top" "$share/examples/manual-test-program.nc")
    grep -q '"status":"ok"' <<<"$report" || fail "m350-sim run on m350-rack-top: $report"

    # proof that the installed machines are read, not the source tree's: break the installed one
    local toml=$share/machines/m350-linear16/machine.toml
    cp "$toml" "$scratch/machine.toml.good"
    printf '\n[[[ broken on purpose by install-test\n' >>"$toml"
    local out status=0
    out=$(cd "$scratch" && "$bin/m350-sim" run "$share/examples/manual-test-program.nc" 2>&1) || status=$?
    [[ $status -ne 0 ]] || fail "m350-sim ran with its installed machine broken: it does not read $share"
    grep -qF "$toml" <<<"$out" || fail "m350-sim's error does not name the installed $toml: $out"
    if [[ "$ui" == ui ]]; then
        status=0
        out=$("$bin/m350-hmi" --lang en --screenshot "$scratch/broken.png" 2>&1) || status=$?
        [[ $status -ne 0 ]] || fail "m350-hmi started with its installed machine broken: it does not read $share"
    fi
    cp "$scratch/machine.toml.good" "$toml"

    if [[ "$ui" == ui ]]; then
        for f in usr/bin/m350-hmi usr/share/man/man1/m350-hmi.1 usr/share/applications/m350-studio.desktop \
                 usr/share/icons/hicolor/scalable/apps/m350-studio.svg; do
            expect_file "$root" "$f"
        done
        version=$("$bin/m350-hmi" --version)
        [[ "$version" =~ ^m350-hmi\ [0-9]+\.[0-9]+\.[0-9]+\ \(commit\ ([0-9a-f]{12}|unknown)\)$ ]] ||
            fail "m350-hmi --version said '$version'"
        "$bin/m350-hmi" --lang en --screenshot "$scratch/$label.png" || fail "m350-hmi --screenshot failed"
        [[ "$(head -c 8 "$scratch/$label.png" | od -An -tx1 | tr -d ' \n')" == 89504e470d0a1a0a ]] ||
            fail "m350-hmi --screenshot did not write a PNG"
        local desktop=$root/usr/share/applications/m350-studio.desktop
        grep -q '^Exec=m350-hmi' "$desktop" || fail "the desktop entry does not start m350-hmi"
        grep -q '^Icon=m350-studio$' "$desktop" || fail "the desktop entry names another icon"
        grep -q '^Name\[zh_CN\]=' "$desktop" || fail "the desktop entry has no Chinese name"
        grep -q '^Categories=.*;$' "$desktop" || fail "the desktop entry has no categories"
    fi
    [[ "$(tree_sum "$share")" == "$before" ]] || fail "running the programs changed files in $share"
}

DESTDIR=$scratch/destdir cmake --install "$build" --prefix /usr >"$scratch/install.log" ||
    { cat "$scratch/install.log"; fail "cmake --install failed"; }
exercise "$scratch/destdir" destdir

(cd "$build" && cpack -G DEB -B "$scratch/package" >"$scratch/cpack.log" 2>&1) ||
    { cat "$scratch/cpack.log"; fail "cpack -G DEB failed"; }
debs=("$scratch"/package/m350-studio_*.deb)
[[ -f "${debs[0]}" ]] || fail "cpack made no m350-studio_*.deb: $(ls "$scratch/package")"
deb=${debs[0]}
contents=$(dpkg-deb -c "$deb")
for f in ./usr/bin/m350-sim ./usr/share/m350-studio/machines/m350-linear16/slib-m.nc ./usr/share/man/man1/m350-sim.1 \
         ./usr/share/doc/m350-studio/README.md; do
    grep -q " $f\$" <<<"$contents" || fail "$deb lacks $f"
done
grep -q ' \./usr/local/' <<<"$contents" && fail "$deb installs into /usr/local"
depends=$(dpkg-deb -f "$deb" Depends)
grep -q 'libc6' <<<"$depends" || fail "Depends lacks libc6 (dpkg-shlibdeps did not run?): $depends"
if [[ "$ui" == ui ]]; then
    for f in ./usr/bin/m350-hmi ./usr/share/applications/m350-studio.desktop ./usr/share/man/man1/m350-hmi.1 \
             ./usr/share/icons/hicolor/scalable/apps/m350-studio.svg; do
        grep -q " $f\$" <<<"$contents" || fail "$deb lacks $f"
    done
    for d in libqt6widgets6 libqt6gui6 qt6-qpa-plugins fonts-wqy-microhei; do
        grep -q "$d" <<<"$depends" || fail "Depends lacks $d: $depends"
    done
fi
echo "$(basename "$deb"): Depends: $depends"
dpkg-deb -x "$deb" "$scratch/package-root"
exercise "$scratch/package-root" package
echo "install-test: ok"
