#!/usr/bin/env bash
# timeIntegration quasiDynamic with law rateState (issue #30), on cases/paperBenchmark's mesh
# (a unit square cut across its width by a horizontal fault: the upper block can slide) in
# rock of E = 30 GPa under an in-situ stress (σ_n = −10 MPa, τ = 5.5 MPa), the top moved
# sideways at V_p = 1e-6 m/s. A velocity-strengthening fault (a = 0.015 > b = 0.01, L = 0.1 mm)
# started at 1e-7 m/s must reach steady sliding: after 10 L/V_p every free node slides at V_p
# (to 1e-3) with the steady-state friction of the regularised law plus radiation damping,
# |τ| = σ̄ a asinh[½ (V/V₀)^(1 − b/a) e^(f₀/a)] + η V node by node (to 1e-6: the integration's
# tolerance), and the tractions of the full solve agree with those S gave the integration
# (relResidual, the balance residual of the written state, ≤ 1e-12). Then: the check fails for
# a law other than the run's (a = 0.016); stopped at t = 300 s and restarted, the run writes
# the very bytes of the uninterrupted one; law rateState without quasiDynamic, and
# quasiDynamic without law rateState, are refused naming the key and the way out.
# Usage: quasiDynamic.sh BIN_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
bin=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
source "$src/utilities/frictionStudy/rateStateBlock.sh"
rateStateBlock "$src" "$work/case" 0.015 0.01 1e-4 1e-7 1000 1e-3 1000 100
cd "$work/case"
cp -r . ../restarted
"$bin/frictionSolver" -case . >log.frictionSolver 2>&1
cat >../check.py <<'PY'
import math, sys
case, a = sys.argv[1], float(sys.argv[2])
b, f0, V0, Vp = 0.01, 0.6, 1e-5, 1e-6
eta = 30e9 / 2.5 / 2 / 3464  # G/(2 c_s), G = E/(2(1 + nu))
lines = open(f"{case}/1000/fractures/fracture.dat").read().splitlines()
h = lines[0][1:].split()
rows = [l.split() for l in lines if not l.startswith("#")]
iV, itau, isn, ist = (h.index(c) for c in ("slipRate", "tau", "sigmaN", "state"))
free = [r for r in rows if r[ist] != "tip"]
assert len(free) >= 10, f"only {len(free)} free nodes"
worstV = max(abs(float(r[iV]) / Vp - 1) for r in free)
worstTau = 0.0
for r in free:
    sb, V = -float(r[isn]), float(r[iV])
    fss = a * math.asinh(0.5 * (V / V0) ** (1 - b / a) * math.exp(f0 / a))
    worstTau = max(worstTau, abs(abs(float(r[itau])) - (sb * fss + eta * V)) / (sb * fss))
status = open(f"{case}/1000/solverStatus").read()
rel = float(status.split("relResidual")[1].split(";")[0])
print(f"V/V_p - 1 up to {worstV:.2e}, |tau| off the steady state by {worstTau:.2e} (relative), "
      f"relResidual {rel:.2e}, {len(free)} nodes")
ok = worstV <= 1e-3 and worstTau <= 1e-6 and rel <= 1e-12
sys.exit(0 if ok else 1)
PY
/usr/bin/python3 ../check.py . 0.015 || { echo "FAIL: not the steady state"; exit 1; }
[[ $(grep -c "^Time = .* converged" log.frictionSolver) == 10 ]] || { echo "FAIL: 10 converged steps expected"; exit 1; }
echo "PASS: steady sliding at V_p with the law's steady-state friction"
if /usr/bin/python3 ../check.py . 0.016 >/dev/null; then echo "FAIL: the check passed for another law"; exit 1; fi
echo "PASS: the check rejects another law (a = 0.016)"

# Restart, byte for byte.
cd ../restarted
sed -i 's/^endTime .*/endTime 300;/' system/controlDict
"$bin/frictionSolver" -case . >log.1 2>&1
sed -i 's/^endTime .*/endTime 1000;/; s/^startFrom .*/startFrom       latestTime;/' system/controlDict
"$bin/frictionSolver" -case . >log.2 2>&1
cd ..
n=0
for f in case/[1-9]*/fractures/fracture.dat case/[1-9]*/solverStatus case/[1-9]*/uniform/frictionState case/[1-9]*/D; do
  cmp -s "$f" "restarted/${f#case/}" || { echo "FAIL: restarted/${f#case/} differs"; exit 1; }
  n=$((n + 1))
done
((n == 40)) || { echo "FAIL: $n files compared, 40 expected"; exit 1; }
grep -q "nextStep" restarted/300/uniform/frictionState
echo "PASS: stopped at 300 s and restarted: $n files byte for byte as the uninterrupted run's"

# Refusals.
cp -r restarted quasiStatic
rm -rf quasiStatic/[1-9]* quasiStatic/VTK quasiStatic/postProcessing
sed -i 's/^timeIntegration .*/timeIntegration quasiStatic;/' quasiStatic/system/frictionSolution
sed -i 's/^startFrom .*/startFrom       startTime;/' quasiStatic/system/controlDict
rc=0
"$bin/frictionSolver" -case quasiStatic >quasiStatic/log 2>&1 || rc=$?
[[ $rc == 1 ]] && grep -q "law rateState (constant/fractureProperties) is integrated in time: set 'timeIntegration { type quasiDynamic; }'" quasiStatic/log ||
  { echo "FAIL: law rateState with quasiStatic (exit $rc)"; cat quasiStatic/log; exit 1; }
cp -r quasiStatic coulomb
sed -i 's/^timeIntegration .*/timeIntegration { type quasiDynamic; }/' coulomb/system/frictionSolution
cat >coulomb/constant/fractureProperties <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object fractureProperties; }
fracture { law coulomb; frictionCoefficient 0.6; }
DICT
rc=0
"$bin/frictionSolver" -case coulomb >coulomb/log 2>&1 || rc=$?
[[ $rc == 1 ]] && grep -q "frictionSolution:.*timeIntegration quasiDynamic integrates rate-and-state faults" coulomb/log ||
  { echo "FAIL: quasiDynamic with law coulomb (exit $rc)"; cat coulomb/log; exit 1; }
echo "PASS: rateState without quasiDynamic and quasiDynamic without rateState are refused"

# 3D: the fault in a cube (tests/regression/cases/faultInCube) with rate-and-state friction
# under an in-situ shear and a lid moved sideways: every step integrated, and the body's
# tractions agree with the law's (balance residual ≤ 1e-12); the 3D tables carry slipRate psi.
cp -r "$src/tests/regression/cases/faultInCube" cube
cd cube
cat >constant/effects <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object effects; }
inSitu { type initialStress; stress (-1e6 -1e6 -1e6 0 0 3e5); }
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
sed -i 's/^elementOrder.*/&\ntimeIntegration { type quasiDynamic; }/' system/frictionSolution
"$bin/splitFractureNodes" -case . >log.splitFractureNodes 2>&1
"$bin/frictionSolver" -case . >log.frictionSolver 2>&1
[[ $(grep -c "^Time = .* converged" log.frictionSolver) == 4 ]] || { echo "FAIL: 3D: 4 converged steps expected"; exit 1; }
head -1 100/fractures/fault.dat | grep -q " slipRate psi state$" || { echo "FAIL: 3D table columns"; exit 1; }
awk '/relResidual/ {gsub(";", "", $2); if ($2 + 0 > 1e-12) bad = 1} END {exit bad}' [1-9]*/solverStatus ||
  { echo "FAIL: 3D balance residual above 1e-12"; exit 1; }
echo "PASS: 3D, 4 steps integrated, balance residual <= 1e-12"

# Stability: stiff events. The same block with a velocity-weakening fault (a = 0.01 < b = 0.015,
# L = 1 µm: the block's stiffness is far below k_crit = σ̄ (b − a)/L) loaded at 1e-9 m/s goes
# through stick-slip cycles, the slip rate from ~1e-14 m/s between events to ~1 m/s in them
# (the integration's steps from hours to milliseconds): every step integrated, at least three
# events over 4e5 s with peaks above 0.1 m/s, recurring at a steady interval (within one
# written step of 5e3 s); stopped just before the second event and restarted, the run writes the
# uninterrupted run's bytes.
cd "$work"
rateStateBlock "$src" "$work/events" 0.01 0.015 1e-6 1e-9 1e6 1e-3 400000 5000
cd events
cp -r . ../eventsRestarted
"$bin/frictionSolver" -case . >log.frictionSolver 2>&1
[[ $(grep -c "^Time = .* converged" log.frictionSolver) == 80 ]] || { echo "FAIL: events: 80 converged steps expected"; exit 1; }
awk '/^Time = / {for (i = 1; i <= NF; i++) if ($i == "peakSlipRate") v = $(i + 1); if (v > 0.1) print $3}' \
  log.frictionSolver >events.txt
/usr/bin/python3 - events.txt <<'PY'
import sys
t = [float(x) for x in open(sys.argv[1]).read().split()]
assert len(t) >= 3, f"{len(t)} events (3 or more expected)"
gaps = [b - a for a, b in zip(t, t[1:])]
assert max(gaps) - min(gaps) <= 5000, f"recurrence intervals {gaps}"
print(f"PASS: {len(t)} events (peak slip rate > 0.1 m/s) at {t} s, recurrence {gaps[0]:g} s")
PY
first=$(head -1 events.txt)
cd ../eventsRestarted
# Stop one written step before the second event, then go on.
second=$(sed -n 2p ../events/events.txt)
stop=$(/usr/bin/python3 -c "print(int(float('$second') - 5000))")
sed -i "s/^endTime .*/endTime $stop;/" system/controlDict
"$bin/frictionSolver" -case . >log.1 2>&1
sed -i 's/^endTime .*/endTime 400000;/; s/^startFrom .*/startFrom       latestTime;/' system/controlDict
"$bin/frictionSolver" -case . >log.2 2>&1
cd ..
n=0
for f in events/[1-9]*/fractures/fracture.dat events/[1-9]*/uniform/frictionState; do
  cmp -s "$f" "eventsRestarted/${f#events/}" || { echo "FAIL: eventsRestarted/${f#events/} differs"; exit 1; }
  n=$((n + 1))
done
((n == 160)) || { echo "FAIL: $n files compared, 160 expected"; exit 1; }
echo "PASS: stopped at $stop s (events from $first s) and restarted through an event: $n files byte for byte"
