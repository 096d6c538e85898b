#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine and passes every test: formatting, the
# full build with warnings as errors under ctest (offscreen), the Debian
# package installed, run and removed (.ci/package.sh), clang-tidy, the
# core and CLI tests again under AddressSanitizer and UndefinedBehaviorSanitizer,
# the core and CLI built for Windows and tested under Wine (.ci/windows.sh),
# and each libFuzzer target for a bounded time.
set -euo pipefail
cd "$(dirname "$0")/.."
bash .ci/install-deps.sh
jobs=$(nproc)
export QT_QPA_PLATFORM=offscreen
# The LinuxCNC programs must pass LinuxCNC's own interpreter (rs274, from
# linuxcnc-uspace): here a missing rs274 fails the test instead of skipping it.
export PROBECYCLE_REQUIRE_RS274=1
export PROBECYCLE_REQUIRE_LINUXCNC=1  # tests/linuxcnc: a missing LinuxCNC fails, not skips

tools/check_format.sh

cmake -S . -B build-ci -DCMAKE_BUILD_TYPE=Release -DPROBECYCLE_WARNINGS_AS_ERRORS=ON
cmake --build build-ci -j"$jobs"
ctest --test-dir build-ci --output-on-failure -j"$jobs"
# Every benchmark must still run without an error, the window's too, with the
# project at the input limits (figures are taken separately, see docs/speed.md).
tools/bench_smoke.sh build-ci/bench/probecycle-bench
large=$(mktemp -d)
python3 tools/make_large_project.py "$large"
PROBECYCLE_LARGE_PROJECT="$large/large.probecycle" \
  tools/bench_smoke.sh build-ci/bench/probecycle-ui-bench
rm -rf "$large"

# The Debian package: built, checked, installed, run and removed.
bash .ci/package.sh build-ci

tools/run_clang_tidy.sh build-ci

cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DPROBECYCLE_SANITIZE=ON \
  -DPROBECYCLE_BUILD_UI=OFF -DPROBECYCLE_BUILD_BENCH=OFF -DPROBECYCLE_WARNINGS_AS_ERRORS=ON
cmake --build build-sanitize -j"$jobs"
ASAN_OPTIONS=detect_leaks=1:halt_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-sanitize --output-on-failure -j"$jobs"

# The core and the CLI for Windows: cross-built with mingw-w64, tested under wine64.
bash .ci/windows.sh build-windows

# Fuzzing: clang with libFuzzer, ASan and UBSan; 20 s a target (docs/building.md:
# longer runs).
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPROBECYCLE_BUILD_FUZZ=ON -DPROBECYCLE_BUILD_UI=OFF -DPROBECYCLE_BUILD_TESTS=OFF \
  -DPROBECYCLE_BUILD_BENCH=OFF -DPROBECYCLE_WARNINGS_AS_ERRORS=ON
cmake --build build-fuzz -j"$jobs"
tools/run_fuzzers.sh build-fuzz 20
