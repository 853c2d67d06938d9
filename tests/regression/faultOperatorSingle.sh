#!/usr/bin/env bash
# timeIntegration quasiDynamic with the right-hand side's dense S stored in single precision
# (`faultOperator { type dense; precision single; }`; README "S in single precision"). On
# cases/seasBP3 at 400 m for 250 years (one earthquake near 166 years), against the same run
# with S in double:
#  * the log says S is stored in single precision, and its size;
#  * the earthquake: the same number of events, onsets within 250 s and peak log10 slip rates
#    within 0.01. Why 250 s: the integrator's own error at its default tolerance moves BP3's
#    onsets by up to 250 s (README, "Tolerance"); S's rounding to float (6e-8 of each entry)
#    must stay below it;
#  * every step converged, and the balance residual of the written state (the body's tractions
#    against the law's) at most 1e-6, the bound the run judges it by;
#  * a run stopped at 100 years and restarted writes the very bytes of the uninterrupted one;
#  * precision auto (the default) keeps the 101-row S of 400 m in double, and the log says
#    S is dense with no word of single precision;
#  * refusals: precision with type hierarchical, an unknown precision: exit 1, the key named,
#    nothing written.
# Usage: faultOperatorSingle.sh BIN_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
bin=$1 src=$2 work=$3
source "$src/tests/regression/bp3Restart.sh"
rm -rf "$work"
mkdir -p "$work"
year=31536000
make_case() {  # DEST FAULT_OPERATOR
  mkdir -p "$(dirname "$1")"
  cp -r "$src/cases/seasBP3" "$1"
  (cd "$1" && ./Allclean >/dev/null && /usr/bin/python3 bp3Case.py --years 250 >/dev/null &&
    ./Allmesh -h 400 >/dev/null && "$bin/splitFractureNodes" -case . >log.splitFractureNodes 2>&1 &&
    sed -i "s/^timeIntegration { type quasiDynamic;/& faultOperator $2/" system/frictionSolution &&
    grep -q "faultOperator" system/frictionSolution)
}
make_case "$work/double/bp3" "{ type dense; precision double; };"
make_case "$work/single/bp3" "{ type dense; precision single; };"
cp -r "$work/single" "$work/restarted"
for c in double single; do
  (cd "$work/$c/bp3" && "$bin/frictionSolver" -case . >log.frictionSolver 2>&1) ||
    { echo "FAIL: the $c run failed"; tail -5 "$work/$c/bp3/log.frictionSolver"; exit 1; }
done
grep -q "S of the right-hand side .*, stored in single precision (.* MB; each entry within 6e-8" \
  "$work/single/bp3/log.frictionSolver" || { echo "FAIL: no single-precision line in the log"; exit 1; }
grep -q "single precision" "$work/double/bp3/log.frictionSolver" &&
  { echo "FAIL: the double run says single precision"; exit 1; }

/usr/bin/python3 -B "$src/cases/seasBP3/bp3Compare.py" "$work/double/bp3" "$work/single/bp3" --bound 250
n=$(grep -c "^Time = .* converged" "$work/single/bp3/log.frictionSolver")
((n == 50)) || { echo "FAIL: single: $n of 50 steps converged"; exit 1; }
awk '/relResidual/ {gsub(";", "", $2); if ($2 + 0 > 1e-6) bad = 1; seen++} END {exit bad || !seen}' \
  "$work"/single/bp3/[1-9]*/solverStatus || { echo "FAIL: balance residual above 1e-6"; exit 1; }
echo "PASS: the earthquake with S in single precision against double; balance within 1e-6"

# Restart through the event, byte for byte.
bp3RestartSameBytes "$bin" "$work/restarted/bp3" "$work/single/bp3"

# The default, precision auto: 101 x 101 is far below 2^22 entries, so double.
make_case "$work/auto/bp3" "{ type auto; };"
cd "$work/auto/bp3"
sed -i "s/^endTime .*/endTime $year;/" system/controlDict
"$bin/frictionSolver" -case . >log.frictionSolver 2>&1 || { echo "FAIL: auto run"; exit 1; }
grep -q "S of the right-hand side dense (faultOperator auto: S_tt 101 x 101, below 1000 rows) (dense products" \
  log.frictionSolver || { echo "FAIL: auto at 400 m: not dense in double"; grep Setup log.frictionSolver; exit 1; }
grep -q "single precision where it has 4194304 entries or more" log.frictionSolver ||
  { echo "FAIL: auto: the settings line does not give the rule"; exit 1; }
echo "PASS: precision auto keeps 101 rows in double and says from where it would not"

# Refusals.
refuse() {  # NAME FAULT_OPERATOR EXPECTED_TEXT
  make_case "$work/bad/$1" "$2"
  cd "$work/bad/$1"
  rc=0
  "$bin/frictionSolver" -case . >log 2>&1 || rc=$?
  ((rc == 1)) || { echo "FAIL: $1: exit $rc, expected 1"; cat log; exit 1; }
  grep -q "$3" log || { echo "FAIL: $1: the message does not name '$3'"; cat log; exit 1; }
  grep -q "frictionSolution" log || { echo "FAIL: $1: the message does not name the file"; cat log; exit 1; }
  ! ls -d [1-9]* postProcessing/faultOutput/*.dat >/dev/null 2>&1 || { echo "FAIL: $1 wrote output"; exit 1; }
  cd "$work"
}
refuse hierarchical "{ type hierarchical; precision single; };" "'precision' applies to a dense S"
refuse word "{ type dense; precision half; };" "precision"
echo "PASS: refusals"
