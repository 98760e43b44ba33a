#!/usr/bin/env bash
# Installs what is missing, builds TrueTurn and its device plugins (Release, build/; the plugins are
# dependencies of the trueturn target, in build/lib/trueturn/plugins) and starts it on the built-in
# simulator with the embedded SQLite history in the user's data folder. Without a display it
# runs the headless closed-loop demo instead. Extra arguments go to trueturn.
set -euo pipefail
cd "$(dirname "$0")"

scripts/install-deps.sh

configure_args=(-S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release)
if [[ ! -f build/CMakeCache.txt ]]; then
    configure_args+=(-DTRUETURN_BUILD_TESTS=OFF -DTRUETURN_BUILD_BENCHMARKS=OFF)
fi
cmake "${configure_args[@]}" >/dev/null
cmake --build build --target trueturn -j "$(nproc)"
plugins=(build/lib/trueturn/plugins/libtrueturn_*.so)
echo "run.sh: ${#plugins[@]} device plugins in build/lib/trueturn/plugins (the Devices page offers them)"

if [[ -z "${DISPLAY:-}" && -z "${WAYLAND_DISPLAY:-}" && -z "${QT_QPA_PLATFORM:-}" ]]; then
    echo "run.sh: no display found (DISPLAY is not set); running the headless closed-loop demo."
    echo "run.sh: for the operator terminal, run on a desktop or set QT_QPA_PLATFORM=offscreen."
    demo=(simulate --preset paper-2012-group1 --delay 2 --parts 200 --profile)
    echo
    echo "== Without control: the barrel-shaped shaft of the simulated lathe =="
    build/app/trueturn "${demo[@]}" --controller open "$@"
    echo
    echo "== With TrueTurn's LQG run-to-run control =="
    exec build/app/trueturn "${demo[@]}" --controller lqg "$@"
fi
exec build/app/trueturn "$@"
