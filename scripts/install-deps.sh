#!/usr/bin/env bash
# Installs the Debian packages TrueTurn needs to build, test and run.
# Used by ./run.sh and ./test.sh; safe to run repeatedly (installs only what is missing).
# Usage: scripts/install-deps.sh [--with-test-tools] [--with-crosscheck-tools]
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config ccache
    qt6-base-dev qt6-base-dev-tools qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
    libqt6sql6-sqlite libqt6sql6-psql qt6-serialport-dev qt6-serialbus-dev libqt6svg6
    qt6-qpa-plugins libgl-dev fonts-dejavu-core
    libeigen3-dev libqcustomplot-dev libboost-dev libsodium-dev libsqlite3-dev
)
# file, help2man, lintian, desktop-file-utils, appstream: scripts/check-package.sh (CPack's dependency list,
# the manual page, the package and metadata checks).
# linuxcnc-uspace: LinuxCNC's standalone G-code interpreter rs274 (/usr/bin/rs274), which the feed-schedule and
# cnc-program tests run on the emitted programs, and LinuxCNC itself, which scripts/start-test-linuxcnc.sh runs
# headless as the simulated lathe of the LinuxCNC tests (its shell tools awk, ipcs, pgrep are in every Debian).
# It must be installed with --no-install-recommends (as below): it recommends a real-time kernel.
test_packages=(
    googletest libgmock-dev libgtest-dev libbenchmark-dev xvfb xauth
    clang libclang-rt-14-dev postgresql linuxcnc-uspace poppler-utils
    python3-scipy python3-statsmodels
    file help2man lintian desktop-file-utils appstream
)
# Octave with its control package: tests/crosscheck/lqg_margins.m, run by hand, produced the fixed reference
# margins of tests/core/control/margins_test.cpp. Not needed by ./test.sh (it would add minutes to CI).
crosscheck_packages=(octave octave-control)
for option in "$@"; do
    case "$option" in
        --with-test-tools) packages+=("${test_packages[@]}") ;;
        --with-crosscheck-tools) packages+=("${crosscheck_packages[@]}") ;;
        *) echo "install-deps: unknown option $option" >&2; exit 2 ;;
    esac
done

missing=()
for p in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
    [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
    echo "install-deps: all ${#packages[@]} packages present"
    exit 0
fi

echo "install-deps: installing ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then
    sudo_cmd=()
elif command -v sudo >/dev/null; then
    sudo_cmd=(sudo)
else
    echo "install-deps: missing packages (${missing[*]}) and neither root nor sudo is available" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
