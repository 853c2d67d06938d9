#!/usr/bin/env bash
# Fuzz the dictionary and mesh readers and whole cases with libFuzzer (clang-14, ASan + UBSan
# + leaks).
#
#   tests/fuzz/run.sh [SECONDS] [BUILD_DIR] [TARGET...]
#
# Builds tests/fuzz as its own CMake project (the library sources compiled with clang and the
# sanitizers) in BUILD_DIR (default <repo>/build/fuzz), then runs each TARGET (default all:
# fuzzDictionary fuzzMesh fuzzCase) for SECONDS (default 60) on a copy of its committed seed
# corpus, so runs never grow the committed one. FRICTION_FUZZ_FLAGS adds libFuzzer flags, e.g.
# "-fork=1 -ignore_crashes=1 -ignore_timeouts=1" to go on after a finding (every reproducer is
# kept in the artifacts folder; a fuzzCase one unpacks into a case folder with
# tests/fuzz/unpackCase.py).
# Exit status: 0 no finding; 1 a crash, leak, UB, timeout or out-of-memory (the reproducer's
# path is printed; minimise it with `<target> -minimize_crash=1 -runs=10000 <file>`, then add
# it to tests/data/fuzz/); 2 the build failed.
set -u
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
seconds="${1:-60}"
build="${2:-$repo/build/fuzz}"
shift 2 2>/dev/null || shift $#
# Absolute: the targets run from their work folders below.
mkdir -p "$build" && build="$(cd "$build" && pwd)"
targets=("$@")
((${#targets[@]})) || targets=(fuzzDictionary fuzzMesh fuzzCase)
cxx="${FRICTION_FUZZ_CXX:-clang++-14}"

# clang and its libFuzzer/sanitizer runtimes are needed by this long test only, so they are
# not in etc/debian-packages: install them here when missing (root, Debian's packages).
if ! command -v "$cxx" >/dev/null || ! dpkg-query -W -f='${Status}' libclang-rt-14-dev 2>/dev/null | grep -q "ok installed"; then
  if [[ $(id -u) -ne 0 ]]; then
    echo "run.sh: needs clang-14 and libclang-rt-14-dev (apt-get install --no-install-recommends clang-14 libclang-rt-14-dev)" >&2
    exit 2
  fi
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends clang-14 libclang-rt-14-dev ||
    { echo "run.sh: installing clang-14 failed" >&2; exit 2; }
fi

cmake -S "$here" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" > "$build.configure.log" 2>&1 \
  || { cat "$build.configure.log"; echo "run.sh: configuring the fuzz build failed" >&2; exit 2; }
# At most as many compile jobs as the machine has cores (ninja alone starts cores + 2).
cmake --build "$build" --parallel "$(nproc)" || { echo "run.sh: building the fuzz targets failed" >&2; exit 2; }

status=0
# One BLAS thread: the fuzz job is meant to take one core, and CHOLMOD's calls are tiny here.
export OPENBLAS_NUM_THREADS=1
for target in "${targets[@]}"; do
  dict=()
  case "$target" in
    fuzzDictionary) corpus=dictionary ;;
    fuzzMesh) corpus=mesh ;;
    fuzzCase) corpus=case; dict=(-dict="$here/case.dict" -max_len=16384) ;;
    *) echo "run.sh: unknown target '$target' (fuzzDictionary, fuzzMesh, fuzzCase)" >&2; exit 2 ;;
  esac
  work="$build/run/$target"
  rm -rf "$work"
  mkdir -p "$work/corpus" "$work/artifacts" "$work/tmp"
  cp "$here/corpus/$corpus/"* "$work/corpus/"
  echo "== $target: ${seconds}s on $(ls "$work/corpus" | wc -l) seeds"
  # -timeout: one input taking 5 s is a hang; -rss_limit_mb: a blow-up, not a machine kill.
  # TMPDIR: fuzzMesh's input file and the dictionary target's include folder stay here.
  # shellcheck disable=SC2086 # FRICTION_FUZZ_FLAGS is a list of flags
  (cd "$work" && TMPDIR="$work/tmp" "$build/$target" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=2048 \
       -print_final_stats=1 -artifact_prefix="$work/artifacts/" "${dict[@]}" ${FRICTION_FUZZ_FLAGS:-} corpus) \
    > "$work/log" 2>&1
  rc=$?
  # Executions: the final stats (one process), or the sum over fork mode's jobs.
  grep -E "^(Done [0-9]+ runs|stat::number_of_executed_units|stat::average_exec_per_sec|stat::peak_rss_mb)" "$work/log"
  grep -E "^#[0-9]+: cov: .* exec/s" "$work/log" | tail -n 1
  findings=$(ls "$work/artifacts")
  if [ "$rc" -ne 0 ] || [ -n "$findings" ]; then
    status=1
    echo "FINDING in $target (exit $rc); log: $work/log"
    grep -E "^(==[0-9]+==ERROR|SUMMARY|.*runtime error)" "$work/log" | head -5
    for f in $findings; do echo "  reproducer: $work/artifacts/$f"; done
  fi
done
exit $status
