#!/usr/bin/env bash
# Fuzz Anatomesh's parsers with libFuzzer (clang, with AddressSanitizer and UBSan):
#   scripts/fuzz.sh [--seconds N] [--runs N] [--build DIR] [--build-only] [TARGET...]
# Targets: NiftiCheck MetaImageCheck NrrdCheck MeditFormat PipelineXml (default: all), each for
# N seconds (default 60) or N executions. The seed corpora are made from Anatomesh's own outputs
# (Testing/Fuzz/make_seeds.py, with the anatomesh Python package on PYTHONPATH or installed); what
# each run finds is kept in DIR/corpus/TARGET, so later runs go on from it. A crash, a sanitizer
# report, a hang (10 s) or an allocation above 2 GB fails the target: its input is kept in
# DIR/findings/ and the exit status is 1. Needs clang and libclang-rt-14-dev.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds=60
runs=""
build="${TMPDIR:-/tmp}/anatomesh-fuzz"
targets=()
build_only=""
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --build) build="$2"; shift 2 ;;
    --build-only) build_only=1; shift ;;
    -h|--help) sed -n 2,10p "$0"; exit 0 ;;
    -*) echo "fuzz.sh: unknown option $1" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
[ ${#targets[@]} -gt 0 ] || targets=(NiftiCheck MetaImageCheck NrrdCheck MeditFormat PipelineXml)
if ! command -v clang++ >/dev/null || ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1; then
  echo "fuzz.sh: clang and libFuzzer are needed (apt-get install clang libclang-rt-14-dev)" >&2
  exit 77
fi

mkdir -p "$build"
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S "$here/Testing/Fuzz" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DPython3_EXECUTABLE=/usr/bin/python3 >"$build/configure.log" 2>&1 || { cat "$build/configure.log"; exit 1; }
fi
cmake --build "$build" -j "${ANATOMESH_JOBS:-2}" >"$build/build.log" 2>&1 || { tail -40 "$build/build.log"; exit 1; }
if [ ! -d "$build/seeds" ]; then
  /usr/bin/python3 "$here/Testing/Fuzz/make_seeds.py" "$build/seeds.tmp" >/dev/null && mv "$build/seeds.tmp" "$build/seeds"
fi

[ -z "$build_only" ] || exit 0

limit=(-max_total_time="$seconds")
[ -z "$runs" ] || limit=(-runs="$runs")
status=0
mkdir -p "$build/findings"
for t in "${targets[@]}"; do
  [ -x "$build/Fuzz$t" ] || { echo "fuzz.sh: no target $t" >&2; exit 2; }
  mkdir -p "$build/corpus/$t"
  extra=()
  [ -f "$here/Testing/Fuzz/$t.dict" ] && extra+=(-dict="$here/Testing/Fuzz/$t.dict")
  # The interpreter behind PipelineXml keeps memory for good: leaks are not findings there.
  log="$build/$t.log"
  if ASAN_OPTIONS="detect_leaks=$([ "$t" = PipelineXml ] && echo 0 || echo 1)" \
    "$build/Fuzz$t" "${limit[@]}" -timeout=10 -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1 \
      -artifact_prefix="$build/findings/$t-" "${extra[@]}" "$build/corpus/$t" "$build/seeds/$t" >"$log" 2>&1; then
    result="no finding"
  else
    result="FINDING (see $log and $build/findings/)"
    status=1
  fi
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  echo "fuzz.sh: $t: ${execs:-?} executions, corpus $(ls "$build/corpus/$t" | wc -l) inputs: $result"
done
exit $status
