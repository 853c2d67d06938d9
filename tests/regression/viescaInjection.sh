#!/usr/bin/env bash
# cases/viescaInjection on a coarser mesh (h = 0.1 m): for T = 0.1, 0.5 and 0.9 the slipping
# half-length a(t) of every written time must lie within h/2 + 0.5 % of Viesca (2021)'s
# λ(T) √(4αt) (viescaError.py --check, run by the case's Allrun), and the summary must hold
# every time of the three runs. Then T = 0.1 again with the pressure computed by diffusion on
# the fault (model diffusion, backward Euler, substeps of 5 ms) instead of the closed form:
# the same check; and that run stopped at t = 0.5 and restarted (startFrom latestTime) must
# write the very bytes of the uninterrupted run (tables and restart states, the diffusion's
# state included).
# Usage: viescaInjection.sh BIN_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
bin=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
cp -r "$src/cases/viescaInjection" "$work/case"
cd "$work/case"
./Allclean >/dev/null
./Allmesh -h 0.1
FRICTION_BIN=$bin ./Allrun
# At every slipping node the Coulomb failure stress change equals the initial margin:
# |tau| = f |sigma'_n| there, so Delta|tau| + f Delta sigma'_n = f sigma'_0 - tau_0 = T f dp
# (0.3 MPa for T = 0.1); the tractions are converged to 1e-10 of 1e7 Pa: 1 Pa is ample.
/usr/bin/python3 - runs/T0.1/1/fractures/fault.dat <<'PY'
import sys
lines = open(sys.argv[1]).read().splitlines()
header = lines[0][1:].split()
rows = [l.split() for l in lines if not l.startswith("#")]
col, st = header.index("deltaCFS"), header.index("state")
slipping = [float(r[col]) for r in rows if r[st] == "slip"]
assert slipping, "no slipping node"
worst = max(abs(v - 3e5) for v in slipping)
assert worst <= 1.0, f"deltaCFS at slipping nodes off the margin 3e5 Pa by {worst} Pa"
print(f"PASS: deltaCFS = 0.3 MPa (the margin) at {len(slipping)} slipping nodes to {worst:.2g} Pa")
PY
rows=$(grep -vc '^#' postProcessing/viesca.dat)
[[ $rows == 29 ]] || { echo "FAIL: postProcessing/viesca.dat has $rows rows, expected 29 (9 + 11 + 9 times)"; exit 1; }
echo "PASS: a(t) within h/2 + 0.5 % of lambda(T) sqrt(4 alpha t) at 29 times, T = 0.1, 0.5, 0.9"

# The computed diffusion, uninterrupted and restarted.
sed -e 's|^    diffusivity 1; .*|    model diffusion; storage 1e-9; transmissivity 1e-9; maxStep 0.005;|' \
  runs/T0.1/constant/effects >effects.diffusion
grep -q "model diffusion" effects.diffusion || { echo "FAIL: the diffusion edit missed"; exit 1; }
for d in diffusion restarted; do
  mkdir -p "$d"
  cp -r runs/T0.1/0 runs/T0.1/constant runs/T0.1/system "$d"/
  cp effects.diffusion "$d/constant/effects"
done
"$bin/frictionSolver" -case diffusion >diffusion/log.frictionSolver 2>&1
/usr/bin/python3 viescaError.py diffusion --T 0.1 --alpha 1 --check
full=$(grep '^times' restarted/system/controlDict)
sed -i 's/^times .*/times (0.0625 0.125 0.25 0.375 0.5);/' restarted/system/controlDict
"$bin/frictionSolver" -case restarted >restarted/log.1 2>&1
sed -i -e "s/^times .*/$full/" -e 's/^startFrom .*/startFrom latestTime;/' restarted/system/controlDict
"$bin/frictionSolver" -case restarted >restarted/log.2 2>&1
grep -q "Restarting from time 0.5" restarted/log.2 || { echo "FAIL: no restart at 0.5"; exit 1; }
n=0
for t in 0.625 0.75 0.875 1; do
  for f in fractures/fault.dat uniform/frictionState; do
    cmp "diffusion/$t/$f" "restarted/$t/$f" || { echo "FAIL: $t/$f differs after a restart"; exit 1; }
    n=$((n + 1))
  done
done
grep -q "pressureChange" diffusion/1/uniform/frictionState || { echo "FAIL: no diffusion state"; exit 1; }
echo "PASS: the computed diffusion meets the bound; restarted at 0.5, $n files byte for byte"
