#!/usr/bin/env bash
# What a quasi-dynamic run costs on the fault, and what S costs to form, on cases/seasBP3's
# meshes (issue #30's performance points). For each fault cell size h [m]:
#  * 50 years of BP3-QD's 60-degree thrust case (interseismic: no event, so every size takes
#    a comparable path) without faultOutput: the Runge-Kutta steps, right-hand sides and their
#    mean cost against (k n)^2, the size of S_tt (the log's "Time integration:" line); a
#    right-hand side is two dense products, S_tt and S_nt, with the slip;
#  * S formed from the one factorisation (interfaceOperator factorisation, the default) and
#    the way of codes that build the fault's Green's function by one volume solve per fault
#    unknown (interfaceOperator blockSolves: one back-substitution per jump unknown, in blocks
#    of 64), on the same mesh, one run each: the setup lines' times and their ratio.
# All runs of one size follow each other; ratios are of one run each on this shared machine.
# Usage: seasCost.sh [BIN_DIR] [WORK_DIR] [h ...]   (default h: 400 200 100 50 25)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=$(cd "${1:-$root/build/bin}" && pwd)
work=${2:-$root/build/seasCost}
shift $(($# < 2 ? $# : 2))
sizes=("$@")
((${#sizes[@]})) || sizes=(400 200 100 50 25)
mkdir -p "$work"
work=$(cd "$work" && pwd)
printf "%6s %8s %10s %9s %11s %10s %12s %12s %12s %8s\n" h kn steps rejected rhs "us/rhs" "ns/(kn)^2" \
  "S factor [s]" "S solves [s]" ratio
for h in "${sizes[@]}"; do
  c=$work/h$h
  rm -rf "$c"
  cp -r "$root/cases/seasBP3" "$c"
  (
    cd "$c"
    ./Allclean >/dev/null
    /usr/bin/python3 bp3Case.py --years 50 >/dev/null
    # No fault outputs: the right-hand sides alone.
    /usr/bin/python3 - <<'PY'
import re
p = "system/controlDict"
s = open(p).read()
i = s.index("faultOutput")
depth, j = 0, s.index("{", i)
for k in range(j, len(s)):
    depth += {"{": 1, "}": -1}.get(s[k], 0)
    if depth == 0:
        break
open(p, "w").write(s[:i] + s[k + 1:])
PY
    ./Allmesh -h "$h" >/dev/null
    "$bin/splitFractureNodes" -case . >log.splitFractureNodes 2>&1
    "$bin/frictionSolver" -case . >log.factorisation 2>&1
    # The one-solve-per-unknown way: one step, S formed by back-substitutions.
    rm -rf [1-9]* VTK postProcessing
    sed -i 's/optimizer { type semismoothNewton;/optimizer { type semismoothNewton; interfaceOperator blockSolves;/' system/frictionSolution
    sed -i 's/^endTime .*/endTime 157680000;/' system/controlDict
    "$bin/frictionSolver" -case . >log.blockSolves 2>&1
  )
  /usr/bin/python3 - "$c" "$h" <<'PY'
import re, sys
c, h = sys.argv[1], sys.argv[2]
def setupSeconds(log):
    # The setup lines of S: the complement (factorisation) or the block solves, and the frame.
    total = 0.0
    for line in open(log):
        if line.startswith("Setup:") and "interface operator" in line:
            total += float(re.search(r": ([0-9.eE+-]+) s \[", line).group(1))
    return total
log = open(c + "/log.factorisation").read()
m = re.search(r"Time integration: (\d+) Runge-Kutta steps accepted, (\d+) rejected, (\d+) right-hand sides in ([0-9.eE+-]+) s \(([0-9.eE+-]+) us each, fault outputs included; S_tt (\d+) x", log)
steps, rejected, rhs, secs, us, kn = m.groups()
sf, sb = setupSeconds(c + "/log.factorisation"), setupSeconds(c + "/log.blockSolves")
print("%6s %8s %10s %9s %11s %10.1f %12.2f %12.4f %12.4f %8.1f" % (h, kn, steps, rejected, rhs, float(us), float(us) * 1e3 / int(kn) ** 2, sf, sb, sb / sf if sf > 0 else float("nan")))
PY
done
