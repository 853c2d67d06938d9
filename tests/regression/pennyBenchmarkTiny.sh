#!/usr/bin/env bash
# utilities/frictionStudy/pennyBenchmark.sh on a tiny mesh (h = a/8, a few seconds): the
# script runs end to end and prints what it promises: both runs' factor lines and peak
# memory, the frictional run's interface operator from the factorisation and its converged
# step, and a positive ratio. (The benchmark itself, 10⁶ unknowns, is not a test.)
# Usage: pennyBenchmarkTiny.sh BIN_DIR SOURCE_DIR WORK_DIR
set -u
bin=$1 src=$2 work=$3
fail() { echo "FAIL [pennyBenchmark.tiny]: $*" >&2; exit 1; }
out=$(bash "$src/utilities/frictionStudy/pennyBenchmark.sh" "$bin" "$work" 0.125 1 0.25 2>&1) ||
  fail "exit $?: $out"
echo "$out"
for want in "linear elastic solve (wall " "frictional solve (wall " \
  "Interface operator: 666 jump unknowns, from the factorisation" "jump unknowns last;" \
  "fault nodes:        273"; do
  grep -qF -- "$want" <<<"$out" || fail "no '$want' in the output"
done
[[ $(grep -c "peak memory [0-9.e+-]* GB" <<<"$out") == 2 ]] || fail "peak memory not given for both runs"
grep -qE "^    Time = 1 .* converged " <<<"$out" || fail "the frictional step did not converge"
ratio=$(sed -n 's/^ratio frictional \/ linear: \([0-9.]*\) .*/\1/p' <<<"$out")
[[ -n $ratio ]] && awk -v r="$ratio" 'BEGIN { exit !(r > 0) }' || fail "no positive ratio: '$ratio'"
echo "pennyBenchmark.tiny: ok (ratio $ratio)"
