#!/usr/bin/env bash
# The iterative volume solver against the factorisation on one 3D mesh (README "The largest 3D
# models"): cases/pennyCrack meshed by gmsh as pennyBenchmark.sh meshes it, then the frictional
# solve (Newton's variant krylov) with each linear solver of SOLVERS, one after the other in
# this run, and a table: wall time, the linear solver's own time, solves and CG iterations,
# peak memory, the ratios amg / cholmod, and the tables' largest difference from the first
# solver's run (parallelCompare.py, as a fraction of each column's scale).
#
# Usage: amgBenchmark.sh [BIN] [WORK] [H HFAR SLOPE]
#   BIN   folder with frictionSolver and splitFractureNodes (default: build/bin)
#   WORK  scratch folder (default: build/amgBenchmark); emptied first
#   H HFAR SLOPE  the mesh (pennyCrack.geo's h, hFar, slope; default 0.03 0.2 0.1: 312 180
#         dofs, 4 178 fault nodes)
# Environment:
#   SOLVERS="cholmod amg"  the linear solvers, in order (the first is the reference of the
#                          differences); a body too large for a factor: SOLVERS=amg
#   ALGO3D=1               gmsh's 3D algorithm (1 Delaunay, as the committed mesh; 10 HXT,
#                          parallel, for the meshes of millions of nodes, where Delaunay's
#                          refinement takes hours)
#   TOL=1e-10              iterativeTolerance of the amg runs
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-$root/build/bin}
work=${2:-$root/build/amgBenchmark}
h=${3:-0.03}
hfar=${4:-0.2}
slope=${5:-0.1}
read -r -a solvers <<<"${SOLVERS:-cholmod amg}"
algo=${ALGO3D:-1}
tol=${TOL:-1e-10}
for tool in frictionSolver splitFractureNodes; do
  [[ -x "$bin/$tool" ]] || { echo "amgBenchmark: $bin/$tool not found (build first)" >&2; exit 1; }
done
command -v gmsh >/dev/null || { echo "amgBenchmark: gmsh not found" >&2; exit 1; }
"$bin/frictionSolver" -listModels | grep -q "linear solvers.*amg" ||
  { echo "amgBenchmark: this build has no amg linear solver (FRICTION_HYPRE)" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"

cp -r "$root/cases/pennyCrack" "$work/base"
rm -f "$work/base"/log.*
sed -i "s/^Mesh.Algorithm3D = [0-9]*;/Mesh.Algorithm3D = $algo;/" "$work/base/constant/mesh/pennyCrack.geo"
echo "Meshing with gmsh (disc h = $h, growth $slope per unit distance up to $hfar, 3D algorithm $algo) ..."
t0=$(date +%s.%N)
(cd "$work/base/constant/mesh" &&
  gmsh -3 -nt 2 -format msh41 -setnumber h "$h" -setnumber hFar "$hfar" -setnumber slope "$slope" \
    pennyCrack.geo -o pennyCrack.msh >"$work/gmsh.log" 2>&1)
echo "$(grep -E '^Info +: [0-9]+ nodes' "$work/gmsh.log" | tail -n 1 | sed 's/^Info *: //') ($(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.0f", b - a }') s)"
sed -i 's/^writeVTK.*//; $a writeVTK no;' "$work/base/system/controlDict"
sed -i "s/^\( *type *\)semismoothNewton;.*/\1semismoothNewton; variant krylov;/" \
  "$work/base/system/frictionSolution"
"$bin/splitFractureNodes" -case "$work/base" >"$work/base/log.splitFractureNodes"
grep -E "^ +nodes:" "$work/base/log.splitFractureNodes" | head -1 | sed 's/^ */fault /'

declare -A wall
for s in "${solvers[@]}"; do
  cp -r "$work/base" "$work/$s"
  keys=""
  [[ $s == amg ]] && keys="iterativeTolerance $tol;"
  sed -i "s/^linearSolver .*/linearSolver    $s; $keys/" "$work/$s/system/frictionSolution"
  echo "Running with linearSolver $s ..."
  t0=$(date +%s.%N)
  "$bin/frictionSolver" -case "$work/$s" >"$work/log.$s" 2>&1 || echo "  (exit $?)"
  wall[$s]=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  rm -rf "$work/$s/constant/splitMesh"  # the largest file; the tables stay for the comparison
done

echo
echo "| linear solver | dofs | fault nodes | setup (factor or hierarchy) [s] | solves (CG iterations) | solve time [s] | Newton iterations, GMRES products | wall [s] | peak memory | wall / ${solvers[0]} | memory / ${solvers[0]} | largest table difference from ${solvers[0]} |"
echo "|---|---:|---:|---:|---|---:|---|---:|---:|---:|---:|---:|"
ref=${solvers[0]}
refMem=$(sed -n 's/^Factorisations .*peak memory \([0-9.e+-]*\) GB.*/\1/p' "$work/log.$ref")
for s in "${solvers[@]}"; do
  log=$work/log.$s
  mem=$(sed -n 's/^Factorisations .*peak memory \([0-9.e+-]*\) GB.*/\1/p' "$log")
  diff="(reference)"
  if [[ $s != "$ref" ]]; then
    diff=$(python3 "$root/tests/regression/parallelCompare.py" --tolerance 1 "$work/$ref" "$work/$s" 2>&1 |
      sed -n 's/.*largest difference \([0-9.e+-]*\) of.*/\1/p' | tail -n 1)
  fi
  its=$(sed -n 's/^Linear solver amg: \([0-9]*\) solves (the check included), \([0-9]*\) CG iterations.*/ (\2 CG iterations)/p' "$log")
  printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s GB | %s | %s | %s |\n' "$s" \
    "$(sed -n 's/^Setup: finite-element spaces.*(\([0-9]*\) dofs.*/\1/p' "$log")" \
    "$(sed -n 's/^Setup: finite-element spaces.*, \([0-9]*\) fracture control nodes).*/\1/p' "$log")" \
    "$(sed -n 's/^Factorisation: [a-zA-Z]* ([a-zA-Z]*, \([0-9.e+-]*\) s)/\1/p' "$log")" \
    "$(sed -n 's/^Factorisations .*back-substitutions \([0-9]*\) .*/\1/p' "$log")$its" \
    "$(sed -n 's/^Factorisations .*back-substitutions [0-9]* (\([0-9.e+-]*\) s).*/\1/p' "$log")" \
    "$(sed -n 's/^Time = .*  iterations \([0-9]*\) .*GMRES products per Newton iteration: \([0-9 ]*\)\].*/\1: \2/p' "$log" | head -n 1)" \
    "${wall[$s]}" "$mem" \
    "$(awk -v a="${wall[$s]}" -v b="${wall[$ref]}" 'BEGIN { printf "%.2f", a / b }')" \
    "$(awk -v a="$mem" -v b="$refMem" 'BEGIN { if (b > 0) printf "%.2f", a / b }')" "$diff"
done
