#!/usr/bin/env bash
# cases/depletion (Jansen & Meulenbroek 2022's base case, GEOS "stableVerticalFault"): the
# case's Allrun (P2, h = 5 m) checks the closed form against Wu et al. 2020's published table
# and Δσ_n, τ along the stuck fault against the closed form (depletionError.py --check: L2 error
# ≤ 0.045 √h, 20 m from the corners ≤ 4 %); then P1 at h = 10 m, the same check. The check
# must be able to fail: the same tables against a closed form with ν = 0.25, or with the
# pressure change's sign flipped, are refused. The fault's pressure is the rock's (no
# faultPressure): p₀ + Δp where the fault has reservoir on both sides, p₀ where it has none,
# in between where one side is reservoir; σ'_n = σ_n + p in every row.
# Usage: depletionCase.sh BIN_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
bin=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
cp -r "$src/cases/depletion" "$work/case"
cd "$work/case"
./Allclean >/dev/null
FRICTION_BIN=$bin ./Allrun
[[ -s postProcessing/depletion.png ]] || { echo "FAIL: no postProcessing/depletion.png"; exit 1; }
for wrong in "--nu 0.25" "--dp 25e6"; do
  if /usr/bin/python3 depletionError.py . --check $wrong >log.wrong 2>&1; then
    echo "FAIL: depletionError.py --check passed with $wrong"; exit 1
  fi
  grep -q "^FAIL: t = 0.5: .*; t = 1: " log.wrong || { echo "FAIL: no diagnosis with $wrong"; cat log.wrong; exit 1; }
done
echo "PASS: the check refuses a closed form with nu = 0.25 or the opposite pressure change"
/usr/bin/python3 - 1/fractures/fault.dat <<'PY'
import sys
lines = open(sys.argv[1]).read().splitlines()
header = lines[0][1:].split()
rows = [dict(zip(header, l.split())) for l in lines if not l.startswith("#")]
rows = [r for r in rows if r["state"] != "tip"]
assert rows
both = one = none = 0
for r in rows:
    y, p = float(r["y"]), float(r["pressure"])
    # 10 significant digits of values near 5e7 Pa: 0.005 Pa each.
    assert abs(float(r["sigmaNEffective"]) - float(r["sigmaN"]) - p) <= 0.05, r
    # Compartments: west -75 < y < 150, east -150 < y < 75 (H = 225 m, throw 75 m); 1 m from
    # their edges, where the nodes' cells are on one side only.
    if abs(y) < 74:
        assert abs(p - 10e6) <= 1.0, r
        both += 1
    elif abs(y) > 151:
        assert abs(p - 35e6) <= 1.0, r
        none += 1
    elif 76 < abs(y) < 149:
        assert 10e6 + 1e5 < p < 35e6 - 1e5, r
        one += 1
assert both and one and none, (both, one, none)
print(f"PASS: fault pressure 10 MPa at {both} nodes, 35 MPa at {none}, between at {one}; "
      "sigma'_n = sigma_n + p in every row")
PY
# P1 at h = 10 m.
./Allclean >/dev/null
./Allmesh -h 10 >/dev/null
sed -i 's/^elementOrder.*/elementOrder    1;/' system/frictionSolution
"$bin/splitFractureNodes" -case . >log.splitFractureNodes 2>&1
"$bin/frictionSolver" -case . >log.frictionSolver 2>&1
grep -q "Elements: P1" log.frictionSolver || { echo "FAIL: not a P1 run"; exit 1; }
/usr/bin/python3 depletionError.py . --check
echo "PASS: P1, h = 10 m"
