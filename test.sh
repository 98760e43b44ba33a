#!/usr/bin/env bash
# Installs what is missing, builds everything (Release, warnings as errors) and runs every test
# with the offscreen Qt platform. Exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")"
started=$(date +%s)

scripts/install-deps.sh --with-test-tools

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DTRUETURN_BUILD_TESTS=ON -DTRUETURN_BUILD_BENCHMARKS=ON -DTRUETURN_WERROR=ON -DTRUETURN_POSTGRES_TESTS=ON
cmake --build build -j "$(nproc)"

# A real PostgreSQL server for the storage tests, on 127.0.0.1 only, and the headless LinuxCNC lathe of the
# LinuxCNC tests (TCP 5007), both stopped on exit.
pg_dir=$(mktemp -d /tmp/trueturn-pg.XXXXXX)
lcnc_dir=$(mktemp -d /tmp/trueturn-lcnc.XXXXXX)
trap 'scripts/start-test-postgres.sh --stop "$pg_dir"; rm -rf "$pg_dir";
      scripts/start-test-linuxcnc.sh --stop "$lcnc_dir"; rm -rf "$lcnc_dir"' EXIT
# Each start's exports are taken in two steps: a start that fails ends this script (eval of a failed command
# substitution would not).
servers=$(scripts/start-test-postgres.sh "$pg_dir" 55432)
eval "$servers"
servers=$(scripts/start-test-linuxcnc.sh "$lcnc_dir" 5007)
eval "$servers"

export QT_QPA_PLATFORM=offscreen
ctest --test-dir build --output-on-failure -j "$(nproc)" --timeout 600

# Fuzzing: a libFuzzer target per byte parser (clang, AddressSanitizer + UndefinedBehaviorSanitizer),
# each run over its seed corpus (tests/fuzz/corpus/) plus a bounded random run. A separate, small
# build without Qt; only the fuzz targets are built.
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Release -DTRUETURN_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++
cmake --build build-fuzz --target fuzz_targets -j "$(nproc)"
ctest --test-dir build-fuzz --output-on-failure -j "$(nproc)" --timeout 120

# The .deb and .tar.gz: built, linted, installed into this machine, run, purged.
scripts/check-package.sh build

echo "test.sh: all tests passed in $(( $(date +%s) - started )) s"
