#!/usr/bin/env bash
# cases/slipWeakeningInjection (Garagash & Germanovich 2012: a fault with linear slip-weakening
# friction under a pressure held at a well): the slipping half-length on the quasi-static branch
# and the loss of equilibrium (status 'nucleation') against the paper's fold, by the case's
# Allrun (gg12Check.py --check). Then:
#  * the check has teeth: a nucleation status edited to 'converged', and a table whose slipping
#    nodes are edited to 'stick', fail it;
#  * the solver stops at the nucleation (no later time folder) with exit status 3, and its log
#    and the step's status say where the patch is;
#  * stopped at t = 3 and restarted (startFrom latestTime), the run writes the very bytes of
#    the uninterrupted run: tables, solver statuses and restart states (the slip path, the
#    law's state, included);
#  * μ_d = μ_s (no weakening) gives Coulomb's answer (law coulomb, f = μ_s) to round-off, with
#    no nucleation.
# Usage: slipWeakeningInjection.sh BIN_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
bin=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
cp -r "$src/cases/slipWeakeningInjection" "$work/case"
cd "$work/case"
./Allclean >/dev/null
FRICTION_BIN=$bin ./Allrun
echo "PASS: Allrun (gg12Check.py --check)"
grep -q "^Stopped at time 6.05: the quasi-static equilibrium is lost" log.frictionSolver ||
  { echo "FAIL: the log does not say the run stopped at the nucleation"; exit 1; }
[[ ! -e 6.1 ]] || { echo "FAIL: a time folder after the nucleation"; exit 1; }
grep -q "status nucleation" 6.05/fractures/fault.dat ||
  { echo "FAIL: the table of 6.05 does not carry the status nucleation"; exit 1; }
grep -q "slipping on 'fault' .* nodes, s from" log.frictionSolver ||
  { echo "FAIL: the nucleation's note does not locate the patch"; exit 1; }
head -1 6.05/fractures/fault.dat | grep -q "slipPath frictionCoefficient nx ny tx ty slipX slipY state$" ||
  { echo "FAIL: the table lacks the columns slipPath frictionCoefficient"; exit 1; }
echo "PASS: stopped at the nucleation (6.05), its status, note and the law's columns"

# Teeth.
cd "$work"
cp -r case noNucleation
sed -i 's/^status *nucleation;/status converged;/' noNucleation/6.05/solverStatus
if /usr/bin/python3 case/gg12Check.py noNucleation --check >noNucleation.log; then
  echo "FAIL: the check passed without a nucleation"; exit 1
fi
grep -q "no step has status 'nucleation'" noNucleation.log
cp -r case stuck
sed -i 's/ slip$/ stick/' stuck/4/fractures/fault.dat
if /usr/bin/python3 case/gg12Check.py stuck --check >stuck.log; then
  echo "FAIL: the check passed with no slipping node at t = 4"; exit 1
fi
grep -q "FAIL: time 4:" stuck.log
echo "PASS: the check rejects a missing nucleation and a wrong half-length"

# Restart, byte for byte.
cp -r case restarted
cd restarted
rm -rf 0.* [1-9]* VTK postProcessing log.frictionSolver
cp system/controlDict controlDict.full
sed -i 's/^stopAt .*/stopAt          endTime;/' system/controlDict
/usr/bin/python3 - system/controlDict <<'PY'
import re, sys
p = sys.argv[1]
s = open(p).read()
s = re.sub(r"times\s*\([^)]*\);", "times (0.25 0.5 0.75 1 1.25 1.5 1.75 2 2.25 2.5 2.75 3);", s)
open(p, "w").write(s)
PY
"$bin/frictionSolver" -case . >log.1 2>&1
cp controlDict.full system/controlDict
sed -i 's/^startFrom .*/startFrom       latestTime;/' system/controlDict
rc=0
"$bin/frictionSolver" -case . >log.2 2>&1 || rc=$?
[[ $rc == 3 ]] || { echo "FAIL: the restarted run's exit status $rc (3 expected: the nucleation)"; exit 1; }
cd "$work"
n=0
for f in case/[0-9]*/fractures/fault.dat case/[0-9]*/solverStatus case/[0-9]*/uniform/frictionState; do
  [[ $f == case/0/* ]] && continue
  g=restarted/${f#case/}
  cmp -s "$f" "$g" || { echo "FAIL: $g differs from the uninterrupted run's"; exit 1; }
  n=$((n + 1))
done
((n >= 90)) || { echo "FAIL: only $n files compared"; exit 1; }
grep -q "slipPath" restarted/3/uniform/frictionState
echo "PASS: stopped at 3 and restarted: $n files byte for byte as the uninterrupted run's"

# No weakening: Coulomb's answer.
for law in weak coulomb; do
  cp -r case $law
  (cd $law && rm -rf 0.* [1-9]* VTK postProcessing log.frictionSolver &&
    sed -i 's/^stopAt .*/stopAt          endTime;/' system/controlDict &&
    /usr/bin/python3 - system/controlDict <<'PY'
import re, sys
p = sys.argv[1]
s = open(p).read()
s = re.sub(r"times\s*\([^)]*\);", "times (1 3 6.5);", s)
open(p, "w").write(s)
PY
  )
done
sed -i 's/dynamicCoefficient  0.36;/dynamicCoefficient  0.6;/' weak/constant/fractureProperties
cat >coulomb/constant/fractureProperties <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object fractureProperties; }
fault { law coulomb; frictionCoefficient 0.6; }
DICT
"$bin/frictionSolver" -case weak >weak/log.frictionSolver 2>&1
"$bin/frictionSolver" -case coulomb >coulomb/log.frictionSolver 2>&1
/usr/bin/python3 - weak coulomb <<'PY'
import sys
def table(c, t):
    lines = open(f"{c}/{t}/fractures/fault.dat").read().splitlines()
    h = lines[0][1:].split()
    rows = [l.split() for l in lines if not l.startswith("#")]
    return h, rows
worst, slipping = 0.0, 0
for t in ("1", "3", "6.5"):
    hw, w = table(sys.argv[1], t)
    hc, c = table(sys.argv[2], t)
    assert "nucleation" not in open(f"{sys.argv[1]}/{t}/solverStatus").read()
    i, j, s = hw.index("slip"), hc.index("slip"), hc.index("state")
    big = max(abs(float(r[j])) for r in c)
    assert big > 0, "nothing slips"
    slipping += sum(r[s] == "slip" for r in c)
    assert [r[hw.index("state")] for r in w] == [r[s] for r in c], f"states differ at {t}"
    worst = max(worst, max(abs(float(a[i]) - float(b[j])) for a, b in zip(w, c)) / big)
assert slipping > 0
assert worst <= 1e-9, f"slip differs from Coulomb's by {worst} (relative)"
print(f"PASS: mu_d = mu_s gives Coulomb's states and slip to {worst:.1e} (relative) at 3 times")
PY
