#!/usr/bin/env bash
# cases/injection on a coarse mesh (h = 100 m on the fault: ~200 fault nodes) to four days:
# Allrun (split, solve, injectionSummary.py --check, the maps) must exit 0. The checks
# (cases/injection/README.md, "What is checked"): every step converged; the in-situ tractions
# before any slip; the pressure at the well's node rising at every step; far from the well
# the closed form's tiny change, nothing more; Coulomb at every node (|tau| = mu |sigma'_n|
# where it slips); slip starting when mu dp reaches the margin; the slipping area never
# shrinking and growing; the slipping nodes inside the pressurised region; normal-fault slip.
# Then: the summary has a row per step and slip by the end, and the pictures are PNGs.
# Usage: injectionCase.sh BIN_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
bin=$1 src=$2 work=$3
fail() { echo "FAIL [injectionCase]: $*"; exit 1; }
rm -rf "$work"
mkdir -p "$work"
cp -r "$src/cases/injection" "$work/case"
cd "$work/case"
./Allclean >/dev/null
./Allmesh -h 100 -hFar 400
sed -i 's/^endTime .*/endTime 345600;/' system/controlDict
FRICTION_BIN=$bin ./Allrun || fail "Allrun exited $?"
grep -q '^PASS' log.injectionSummary || fail "no PASS line in log.injectionSummary"
steps=$(grep -c '^Time = ' log.frictionSolver)
rows=$(grep -cE '^[0-9.]+(e[-+]?[0-9]+)?  ' postProcessing/summary.dat)
((steps == 18 && rows == steps)) || fail "$steps steps, $rows summary rows (expected 18 each)"
last=$(grep -E '^[0-9.]+(e[-+]?[0-9]+)?  ' postProcessing/summary.dat | tail -n 1)
read -r _ _ _ slipping _ <<<"$last"
((slipping >= 5)) || fail "$slipping slipping nodes at four days, expected at least 5: $last"
isPng() { [[ -s $1 && $(head -c 8 "$1" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]]; }
n=0
for png in postProcessing/fault_t*.png postProcessing/fracture_fault_profile.png; do
  isPng "$png" || fail "$png missing or not a PNG"
  n=$((n + 1))
done
((n >= 3)) || fail "only $n pictures"
head -n 1 postProcessing/fault_strike.csv | grep -q ',pressure,sigmaNEffective$' ||
  fail "the profile CSV has no pressure columns"
echo "PASS: cases/injection (coarse, four days): $steps steps, $slipping slipping nodes at the end, $n pictures"
