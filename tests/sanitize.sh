#!/usr/bin/env bash
# The whole test suite (all labels but long) in a Debug build (assertions on) instrumented with
# AddressSanitizer, LeakSanitizer and UndefinedBehaviorSanitizer (FRICTION_SANITIZE).
#
#   tests/sanitize.sh [BUILD_DIR] [JOBS]
#
# Configures and builds the repository in BUILD_DIR (default <repo>/build-asan, its own folder:
# the Release build is untouched), then runs `ctest -LE long` there. -O1 keeps Eigen's templates
# fast enough that the regression cases finish; it removes no check (NDEBUG stays unset).
# Exit status: ctest's (0 clean; non-zero: a failing test, an ASan/UBSan report, a leak);
# 2 configuring or building failed. The report of a sanitizer is in the failing test's output
# (ctest --output-on-failure); BUILD_DIR/Testing/Temporary/LastTest.log has all of them.
set -u
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/.." && pwd)"
build="${1:-$repo/build-asan}"
jobs="${2:-2}"

generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
cmake -S "$repo" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Debug \
      -DCMAKE_CXX_FLAGS_DEBUG="-g -O1" -DFRICTION_SANITIZE=address,undefined \
  || { echo "sanitize.sh: configuring $build failed" >&2; exit 2; }
cmake --build "$build" -j "$jobs" || { echo "sanitize.sh: building $build failed" >&2; exit 2; }

# halt_on_error / -fno-sanitize-recover: the first report ends the process with an error, so
# the test that met it fails. exitcode 99: the default (1) is also the binaries' "bad input"
# code, which the error-path tests expect. The suppressions cover only the uninstrumented
# libraries (CHOLMOD, OpenBLAS, OpenMPI) and say why each entry is there. fast_unwind_on_malloc=0:
# the fast unwinder loses OpenMPI's frames (its plugins are unloaded at MPI_Finalize), and the
# suppressions match those frames' names.
export ASAN_OPTIONS="exitcode=99:detect_leaks=1:halt_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1:fast_unwind_on_malloc=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="exitcode=99:print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
export LSAN_OPTIONS="exitcode=99:suppressions=$here/sanitize.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
cd "$build" && ctest -LE long -j "$jobs" --output-on-failure
status=$?

# A report from a process whose exit status its test does not look at (a helper, a process a
# script kills) would pass unseen: look for reports in everything the tests wrote.
reports=$(grep -rIl -E "ERROR: (Address|Leak)Sanitizer|runtime error:" "$build/tests" "$build/Testing" 2>/dev/null)
if [ -n "$reports" ]; then
  echo "sanitize.sh: sanitizer reports in:" >&2
  echo "$reports" >&2
  status=1
fi
exit $status
