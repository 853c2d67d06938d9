#!/usr/bin/env bash
# Convergence under refinement (P1 or P2) of the slip where 3D fault surfaces cross (issue #31):
# the unit cube of tests/regression/cases/faultNetworkBox (base held, lid moved by
# (0.002, 0.001, -0.001) m) with its two crossing faults only (networkConvergence3d.geo:
# 'main' on z = 1/2, 'crossing' inclined 60° through it along x = 0.45), Coulomb mu_f 0.2,
# one step, semismooth Newton to 1e-12; fault mesh size h = 0.1, 0.05, 0.025 and the
# reference 0.0125 m (P1), or 0.1, 0.075, 0.05 and the reference 0.0333 m (P2: four times the
# control nodes of P1 at one h). networkConvergence3d.py prints per fault the slip error
# against the reference near the intersection curve, away from it, and on the curve, with the
# observed orders. Runs one after another: P1 ~6 min on 2 cores, nearly all the reference's
# (74337 dofs, 6985 control nodes: the factorisation and Newton's dense interface operator,
# 12.5 GB peak); P2 ~4 min, 6.2 GB peak (the reference: 4185 control nodes, 203 s).
# Usage: networkConvergence3d.sh [BIN_DIR] [WORK_DIR] [ORDER (1 or 2)]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-$root/build/bin}
order=${3:-1}
work=${2:-$root/build/networkConvergence3d}
case $order in
1) sizes=(0.1 0.05 0.025 0.0125) ;;
2) sizes=(0.1 0.075 0.05 0.0333) ;;
*) echo "ORDER must be 1 or 2, not '$order'" >&2; exit 1 ;;
esac
# shellcheck source=timedRun.sh
source "$root/utilities/frictionStudy/timedRun.sh"
command -v gmsh >/dev/null || { echo "gmsh not found (Debian package gmsh)" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"

header='FoamFile { version 2.0; format ascii; class dictionary; object'
runs=()
for h in "${sizes[@]}"; do
  c=$work/h$h
  cp -r "$root/tests/regression/cases/faultNetworkBox" "$c"
  "$c/Allclean" >/dev/null
  rm -f "$c/constant/mesh/"*.msh
  printf '%s meshDict; }\nmesh "constant/mesh/network.msh";\nfractures (main crossing);\n' \
    "$header" >"$c/system/meshDict"
  printf '%s fractureProperties; }\nmain { law coulomb; frictionCoefficient 0.2; }\ncrossing { law coulomb; frictionCoefficient 0.2; }\n' \
    "$header" >"$c/constant/fractureProperties"
  sed -i 's/^deltaT .*/deltaT          1;/; s/^writeVTK .*/writeVTK        no;/;
          s/^writePrecision .*/writePrecision  12;/' "$c/system/controlDict"
  sed -i 's/tolerance *1e-10;/tolerance       1e-12;/' "$c/system/frictionSolution"
  sed -i "s/^elementOrder .*/elementOrder    $order;/" "$c/system/frictionSolution"
  gmsh -3 -format msh41 -setnumber h "$h" "$root/utilities/frictionStudy/networkConvergence3d.geo" \
    -o "$c/constant/mesh/network.msh" >"$c/log.gmsh" 2>&1
  "$bin/splitFractureNodes" -case "$c" >"$c/log.splitFractureNodes" 2>&1
  t=$(timedRun "$bin" "$c")
  grep -q ' converged' "$c/log.frictionSolver" || { echo "$c: not converged" >&2; exit 1; }
  its=$(grep -o '^Time = 1  iterations [0-9]*' "$c/log.frictionSolver" | awk '{ print $5 }')
  nodes=$(grep -o '[0-9]* fracture control nodes' "$c/log.frictionSolver" | head -1)
  echo "h = $h m: $nodes, Newton iterations $its, frictionSolver ${t} s"
  runs+=("$h=$c/1/fractures")
done
/usr/bin/python3 -B "$root/utilities/frictionStudy/networkConvergence3d.py" "${runs[@]}"
