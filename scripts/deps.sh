#!/usr/bin/env bash
# Installs the Debian packages M350 Studio needs, only when they are missing.
# Quiet and idempotent when everything is already present.
set -euo pipefail

REQUIRED_PACKAGES=(
    cmake ninja-build g++ pkg-config
    libeigen3-dev nlohmann-json3-dev libcli11-dev libtomlplusplus-dev
    libgtest-dev libgmock-dev libbenchmark-dev
    qt6-base-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
    qt6-charts-dev libqt6opengl6-dev  # Qt Charts (the breakage monitor); its CMake config needs Qt6OpenGL
    xvfb xauth
    dpkg-dev  # dpkg-shlibdeps: the Debian package's Depends (cpack -G DEB, tests/install)
    clang libclang-rt-dev  # clang++ and libclang_rt.fuzzer-x86_64.a: the fuzz step of scripts/test.sh
    fonts-wqy-microhei fonts-dejavu-core
)
# Provides /usr/bin/rs274: only used for benchmark comparisons and a differential test.
OPTIONAL_PACKAGE=linuxcnc-uspace

export DEBIAN_FRONTEND=noninteractive

is_installed() {
    local status
    status=$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null) || return 1
    [[ "$status" == "install ok installed" ]]
}

# Runs a command as root: directly when we are root, otherwise through sudo.
as_root() {
    if [[ "$(id -u)" -eq 0 ]]; then
        "$@"
    elif command -v sudo >/dev/null 2>&1; then
        sudo env DEBIAN_FRONTEND=noninteractive "$@"
    else
        echo "deps.sh: need root or sudo to run: $*" >&2
        return 1
    fi
}

apt_updated=0
apt_update_once() {
    if [[ "$apt_updated" -eq 0 ]]; then
        as_root apt-get update -qq
        apt_updated=1
    fi
}

apt_install() {
    as_root apt-get install -y -qq --no-install-recommends "$@"
}

missing=()
for pkg in "${REQUIRED_PACKAGES[@]}"; do
    is_installed "$pkg" || missing+=("$pkg")
done

if [[ "${#missing[@]}" -gt 0 ]]; then
    echo "deps.sh: installing missing packages: ${missing[*]}"
    apt_update_once
    apt_install "${missing[@]}"
fi

if ! is_installed "$OPTIONAL_PACKAGE"; then
    if ! { apt_update_once && apt_install "$OPTIONAL_PACKAGE"; } >/dev/null 2>&1; then
        echo "deps.sh: optional $OPTIONAL_PACKAGE (rs274) not installed; rs274 comparisons will be skipped."
    fi
fi
