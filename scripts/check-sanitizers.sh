#!/usr/bin/env bash
# Build the C++ modules and tests with AddressSanitizer and UndefinedBehaviorSanitizer (gcc) in a
# separate folder and run the C++ tests there:
#   scripts/check-sanitizers.sh [BUILD_DIR] [ctest arguments...]
# (default /tmp/anatomesh-asan). The Python package and the plugin are left out: they load into
# interpreters built without the sanitizers. A sanitizer report aborts the test that made it, so
# ctest's summary is the verdict; the reports are in BUILD_DIR/Testing/Temporary/LastTest.log.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-/tmp/anatomesh-asan}"
shift || true
mkdir -p "$build"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DANATOMESH_SANITIZERS="address;undefined" \
  -DANATOMESH_WRAP_PYTHON=OFF -DANATOMESH_BUILD_PLUGIN=OFF >"$build/configure.log" 2>&1 ||
  { cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j "${ANATOMESH_JOBS:-2}" >"$build/build.log" 2>&1 || { tail -40 "$build/build.log"; exit 1; }
cd "$build"
# Leaks are reported too; VTK's and ITK's singletons that live until exit are not ours.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$here/scripts/lsan.supp}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1:suppressions=$here/scripts/ubsan.supp}"
ctest --output-on-failure -j "${ANATOMESH_JOBS:-2}" --timeout 3600 -E '^(Benchmark|Python|ParaView|Docs|Install)' "$@"
