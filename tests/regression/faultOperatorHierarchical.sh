#!/usr/bin/env bash
# timeIntegration quasiDynamic with `faultOperator hierarchical` (S of the right-hand side
# compressed to an H-matrix; README "Earthquake cycles", docs/method.md). On cases/seasBP3 at
# 400 m for 250 years (one earthquake near 166 years), against the same run with the dense S:
#  * the log says what was compressed (low-rank blocks, a fraction of the dense entries);
#  * the earthquake: the same number of events (max slip rate above 1e-3 m/s), onsets within
#    1 000 s and peak log10 slip rates within 0.01. Why 1 000 s: the integrator's own error at
#    its default tolerance moves BP3's onsets by up to 250 s, and by 2.6e3 s at 1e-7 (README,
#    "Tolerance"); the compression at 1e-6 must stay below the latter;
#  * with tolerance 1e-12 the onsets come within 1 s of the dense run's: the difference is the
#    compression's, and it vanishes with it;
#  * every step converged, the balance residual of the written state (the body's tractions
#    against the law's) at most the compression's tolerance;
#  * a run stopped at 100 years and restarted writes the very bytes of the uninterrupted one
#    (the H-matrix is formed again, alike);
#  * 3D (tests/regression/cases/faultInCube, two tangential components per node, leaves of 4
#    nodes): the slips of a dense and a compressed (1e-10) run agree to 1e-8;
#  * faultOperator auto (the default): dense below 1 000 rows of S_tt, compressed from there,
#    as the log says;
#  * refusals: a tolerance out of its bounds, an unknown type, an unknown key: exit 1, the key
#    named, nothing written.
# Usage: faultOperatorHierarchical.sh BIN_DIR SOURCE_DIR WORK_DIR
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
make_case "$work/dense/bp3" "dense;"
make_case "$work/h6/bp3" "{ type hierarchical; tolerance 1e-6; leafSize 16; };"
make_case "$work/h12/bp3" "{ type hierarchical; tolerance 1e-12; leafSize 16; };"
cp -r "$work/h6" "$work/restarted"
for c in dense h6 h12; do
  (cd "$work/$c/bp3" && "$bin/frictionSolver" -case . >log.frictionSolver 2>&1) ||
    { echo "FAIL: the $c run failed"; tail -5 "$work/$c/bp3/log.frictionSolver"; exit 1; }
done
grep -q "H-matrix .*[1-9][0-9]* low-rank blocks" "$work/h6/bp3/log.frictionSolver" ||
  { echo "FAIL: no H-matrix line in the log"; exit 1; }
grep -q "H-matrix" "$work/dense/bp3/log.frictionSolver" && { echo "FAIL: the dense run compressed"; exit 1; }

/usr/bin/python3 -B "$src/cases/seasBP3/bp3Compare.py" "$work/dense/bp3" "$work/h6/bp3" --bound 1000
/usr/bin/python3 -B "$src/cases/seasBP3/bp3Compare.py" "$work/dense/bp3" "$work/h12/bp3" --bound 1
for c in h6 h12; do
  n=$(grep -c "^Time = .* converged" "$work/$c/bp3/log.frictionSolver")
  ((n == 50)) || { echo "FAIL: $c: $n of 50 steps converged"; exit 1; }
done
awk '/relResidual/ {gsub(";", "", $2); if ($2 + 0 > 1e-6) bad = 1; seen++} END {exit bad || !seen}' \
  "$work"/h6/bp3/[1-9]*/solverStatus || { echo "FAIL: balance residual above 1e-6"; exit 1; }
echo "PASS: the earthquake of the compressed runs against the dense run's; balance within 1e-6"

# Restart through the event, byte for byte.
bp3RestartSameBytes "$bin" "$work/restarted/bp3" "$work/h6/bp3"

# 3D: two tangential components per node.
cube() {  # DEST FAULT_OPERATOR
  cp -r "$src/tests/regression/cases/faultInCube" "$1"
  cd "$1"
  cat >constant/effects <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object effects; }
inSitu { type initialStress; stress (-1e6 -1e6 -1e6 0 0 6.1e5); }
DICT
  cat >constant/fractureProperties <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object fractureProperties; }
fault
{
    law rateState; a 0.015; b 0.01; characteristicSlip 1e-5; referenceFriction 0.6;
    referenceSlipRate 1e-5; initialSlipRate 1e-8; radiationDamping 1e5;
}
DICT
  sed -i 's/value table ((0 (0 0 0)) (1 (0.002 0.001 -0.001)));/value table ((0 (0 0 0)) (100 (1e-4 0 0)));/' 0/D
  grep -q "(100 (1e-4 0 0))" 0/D
  sed -i 's/^endTime .*/endTime 100;/; s/^deltaT .*/deltaT 25;/' system/controlDict
  sed -i "s/^elementOrder.*/&\ntimeIntegration { type quasiDynamic; faultOperator $2 }/" system/frictionSolution
  "$bin/splitFractureNodes" -case . >log.splitFractureNodes 2>&1
  "$bin/frictionSolver" -case . >log.frictionSolver 2>&1 || { echo "FAIL: 3D run $1"; tail -5 log.frictionSolver; exit 1; }
  cd "$work"
}
cube "$work/cube" "dense;"
cube "$work/cubeH" "{ type hierarchical; tolerance 1e-5; leafSize 4; }"
# The right-hand side's S is on the nodes rate-and-state moves: the 24 inside the tip line
# of 44 (a held node's slip is 0, its rows unused). Too few for a block to compress at 1e-5
# (a 3 × 4-node block needs rank 4 or more), so the H-matrix is all dense blocks here: the run
# checks the moved nodes' rows and columns through the H-matrix's orderings in 3D against the
# dense product (compression itself is tested on lines and squares in [HierarchicalMatrix]).
grep -q "on the 24 nodes that rate-and-state moves, of 44" "$work/cubeH/log.frictionSolver" ||
  { echo "FAIL: 3D: the right-hand side's S is not on the 24 moved nodes"; exit 1; }
grep -q "H-matrix 72 x 48: .* dense" "$work/cubeH/log.frictionSolver" ||
  { echo "FAIL: 3D: no H-matrix of the moved nodes"; exit 1; }
/usr/bin/python3 - "$work/cube/100/fractures/fault.dat" "$work/cubeH/100/fractures/fault.dat" <<'PY'
import sys
def slips(path):
    text = [l for l in open(path) if l.strip()]
    head = text[0].lstrip("# ").split()
    rows = [l.split() for l in text[1:] if not l.startswith("#")]
    cols = [i for i, h in enumerate(head) if h in ("slip1", "slip2")]
    return [[float(r[i]) for i in cols] for r in rows], [head[i] for i in cols]
(a, names), (b, _) = slips(sys.argv[1]), slips(sys.argv[2])
if not a or not names or len(a) != len(b):
    sys.exit("FAIL: 3D tables: %d and %d rows, columns %s" % (len(a), len(b), names))
scale = max(abs(x) for r in a for x in r)
diff = max(abs(x - y) for ra, rb in zip(a, b) for x, y in zip(ra, rb))
print("3D: %d nodes, columns %s, max |slip| %.3e m, largest difference %.2e" % (len(a), names, scale, diff))
if not scale > 0 or diff > 1e-4 * scale:
    sys.exit("FAIL: 3D slips of the compressed run differ by %.3g (bound 1e-4 of %.3g)" % (diff, scale))
PY
echo "PASS: 3D, compressed against dense"

# The default, faultOperator auto: dense below 1 000 rows of the right-hand side's S_tt (400 m,
# P1: 101 of the 152 nodes move, the rest creep), compressed from there (50 m, P2: over 1 000),
# and the log says which and why.
make_case "$work/auto/bp3" ""
cd "$work/auto/bp3"
sed -i 's/ faultOperator / /' system/frictionSolution
! grep -q faultOperator system/frictionSolution || { echo "FAIL: auto: faultOperator still set"; exit 1; }
sed -i "s/^endTime .*/endTime $year;/" system/controlDict
"$bin/frictionSolver" -case . >log.frictionSolver 2>&1
grep -q "S of the right-hand side dense (faultOperator auto: S_tt 101 x 101, below 1000 rows)" log.frictionSolver ||
  { echo "FAIL: auto at 400 m: no 'dense' line"; grep Setup log.frictionSolver; exit 1; }
cp -r "$src/cases/seasBP3" "$work/autoP2"
cd "$work/autoP2"
./Allclean >/dev/null && /usr/bin/python3 bp3Case.py --years 1 --order 2 >/dev/null && ./Allmesh -h 50 >/dev/null &&
  "$bin/splitFractureNodes" -case . >log.splitFractureNodes 2>&1
"$bin/frictionSolver" -case . >log.frictionSolver 2>&1 || { echo "FAIL: auto at 50 m, P2"; exit 1; }
grep -q "S_tt and S_nt of the right-hand side (faultOperator auto: S_tt [0-9]* rows, from 1000) H-matrix" \
  log.frictionSolver || { echo "FAIL: auto at 50 m, P2: not compressed"; grep Setup log.frictionSolver; exit 1; }
echo "PASS: faultOperator auto: dense at 101 rows, compressed at $(grep -o 'auto: S_tt [0-9]* rows' log.frictionSolver)"

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
refuse tolerance "{ type hierarchical; tolerance 0.5; };" "tolerance"
refuse type "compressed;" "faultOperator"
refuse key "{ type hierarchical; rank 4; };" "rank"
echo "PASS: refusals"
