#!/usr/bin/env bash
# utilities/frictionStudy/pennyBenchmark.sh on a tiny mesh (h = a/8, a few seconds), with both
# variants of Newton: the script runs end to end and prints what it promises: every run's
# factor line and peak memory, the condensed run's interface operator from the factorisation,
# converged steps, positive ratios, and one table whose krylov row factors the plain K (the
# linear run's factor: no border of jump unknowns). (The benchmark itself is not a test.)
# Usage: pennyBenchmarkTiny.sh BIN_DIR SOURCE_DIR WORK_DIR
set -u
bin=$1 src=$2 work=$3
fail() { echo "FAIL [pennyBenchmark.tiny]: $*" >&2; exit 1; }
out=$(VARIANTS="condensed krylov" bash "$src/utilities/frictionStudy/pennyBenchmark.sh" "$bin" "$work" 0.125 1 0.25 2>&1) ||
  fail "exit $?: $out"
echo "$out"
for want in "linear elastic solve (wall " "frictional solve, variant condensed (wall " \
  "frictional solve, variant krylov (wall " \
  "Interface operator: 666 jump unknowns, from the factorisation" "jump unknowns last;" \
  "fault nodes:        273"; do
  grep -qF -- "$want" <<<"$out" || fail "no '$want' in the output"
done
[[ $(grep -c "peak memory [0-9.e+-]* GB" <<<"$out") == 3 ]] || fail "peak memory not given for all three runs"
[[ $(grep -cE "^    Time = 1 .* converged " <<<"$out") == 3 ]] || fail "a step did not converge"
for v in condensed krylov; do
  ratio=$(sed -n "s/^ratio frictional ($v) \/ linear: \([0-9.]*\) .*/\1/p" <<<"$out")
  [[ -n $ratio ]] && awk -v r="$ratio" 'BEGIN { exit !(r > 0) }' || fail "no positive ratio for $v: '$ratio'"
done
# The table: the factor column (4th) of the krylov row is the linear row's; condensed's is larger.
factor() { awk -F' [|] ' -v r="$1" '$1 == "| " r { print $4 }' <<<"$out"; }
[[ -n $(factor linear) && $(factor krylov) == "$(factor linear)" ]] ||
  fail "the krylov run's factor '$(factor krylov)' is not the plain K's '$(factor linear)'"
[[ -n $(factor condensed) && $(factor condensed) != "$(factor linear)" ]] ||
  fail "the condensed run's factor is not bordered: '$(factor condensed)'"
grep -qE "^[|] krylov [|] 273 [|] 666 [|] .* [|] 26 [|] [0-9]+ [|] [0-9 ]+ [(]sum [0-9]+[)] [|]" <<<"$out" ||
  fail "no krylov row with 273 nodes, 666 jump unknowns, 26 set-up solves and GMRES products"
echo "pennyBenchmark.tiny: ok"
