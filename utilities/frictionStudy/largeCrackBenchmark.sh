#!/usr/bin/env bash
# The cost of friction at scale (issue: accuracy/time study, second target): the inclined
# crack on a mesh of about a million unknowns; the whole frictional solve, factorisation
# included, against one linear elastic solve (factorisation plus one back-substitution) on
# the same mesh, measured in one run and printed as a ratio.
# Usage: largeCrackBenchmark.sh [BIN_DIR] [WORK_DIR] [HFAR]    (HFAR: far-field size, 0.0015)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-$root/build/bin}
work=${2:-$root/build/largeCrack}
hfar=${3:-0.0015}
rm -rf "$work" && mkdir -p "$work"

cp -r "$root/cases/inclinedCrack" "$work/friction"
rm -f "$work/friction"/log.*
echo "Meshing with gmsh (crack h = a/32, far field $hfar) ..."
(cd "$work/friction/constant/mesh" &&
  gmsh -2 -format msh41 -setnumber h 0.0015625 -setnumber hFar "$hfar" inclinedCrack.geo \
    -o inclinedCrack.msh >"$work/gmsh.log" 2>&1)
sed -i 's/^writeVTK.*//; $a writeVTK no;' "$work/friction/system/controlDict"
cp -r "$work/friction" "$work/linear"
# The linear reference: the same mesh with no fracture (no control loop, one solve).
sed -i 's/^fractures .*/fractures ();/' "$work/linear/system/meshDict"
sed -i '/^crack/,$d' "$work/linear/constant/fractureProperties"

"$bin/splitFractureNodes" -case "$work/friction" >"$work/friction/log.splitFractureNodes"
"$bin/splitFractureNodes" -case "$work/linear" >"$work/linear/log.splitFractureNodes"
grep -E "points:|tips" "$work/friction/log.splitFractureNodes" | head -3

# shellcheck source=timedRun.sh
source "$root/utilities/frictionStudy/timedRun.sh"
run() { timedRun "$bin" "$1"; }  # run CASE: wall seconds of frictionSolver
tl=$(run "$work/linear")   # the reference first, then each variant, on the same machine state
for variant in condensed krylov; do
  rm -rf "$work/friction/1" "$work/friction/postProcessing"
  sed -i "s/type            semismoothNewton;.*/type semismoothNewton; variant $variant;/; s/type semismoothNewton; variant [a-z]*;/type semismoothNewton; variant $variant;/" \
    "$work/friction/system/frictionSolution"
  tf=$(run "$work/friction")
  cp "$work/friction/log.frictionSolver" "$work/log.friction.$variant"
  declare "t_$variant=$tf"
done

dofs=$(sed -n 's/.* \([0-9]*\) dofs.*/\1/p' "$work/friction/log.frictionSolver")
factor=$(sed -n 's/.*Factorisation: ok ([a-zA-Z]*, \([0-9.e-]*\) s).*/\1/p' "$work/linear/log.frictionSolver")
echo
echo "unknowns (P1 dofs):                $dofs"
echo "linear elastic solve (wall):        $tl s (factorisation $factor s)"
grep "^Factorisations" "$work/linear/log.frictionSolver"
for variant in condensed krylov; do
  tf=t_$variant
  line=$(grep "Time = " "$work/log.friction.$variant")
  echo "frictional solve, $variant (wall): ${!tf} s  [${line%%  \[*}]"
  grep "^Factorisations" "$work/log.friction.$variant"
  echo "ratio frictional / linear ($variant): $(awk -v a="${!tf}" -v b="$tl" 'BEGIN { printf "%.2f", a / b }')  (target <= 3)"
done
