#!/usr/bin/env bash
# The distributed engine on this machine (issue 14, part 2): cases/pennyCrack (3D, Coulomb,
# condensed Newton with S from the factorisation) meshed by gmsh, solved by
#   frictionSolver (cholmod, serial)            the reference
#   frictionSolver (mumps, 1 rank)
#   mpirun -np 2 frictionSolver -parallel      (mumps, 2 ranks)
# and, per run, the wall time, the factorisation's time, MUMPS's memory on the largest rank and
# on all ranks, and every rank's peak resident memory, with the ratios measured in this one
# run. The fracture tables of the three runs are compared (tests/regression/parallelCompare.py).
#
# Usage: parallelBenchmark.sh [BIN_DIR] [WORK_DIR] [H HFAR SLOPE] [RANKS...]
#   defaults: build/bin, build/parallelBenchmark, h = a/16 on the disc growing by 0.1 per unit
#   distance up to 0.25 a (~5 min on 2 cores, ~4 GB), ranks 2.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-$root/build/bin}
work=${2:-$root/build/parallelBenchmark}
h=${3:-0.0625}
hfar=${4:-0.25}
slope=${5:-0.1}
shift $(($# < 5 ? $# : 5))
ranks=("$@")
((${#ranks[@]})) || ranks=(2)
for tool in frictionSolver splitFractureNodes; do
  [[ -x "$bin/$tool" ]] || { echo "parallelBenchmark: $bin/$tool not found (build first)" >&2; exit 1; }
done
command -v gmsh >/dev/null || { echo "parallelBenchmark: gmsh not found" >&2; exit 1; }
command -v mpirun >/dev/null || { echo "parallelBenchmark: mpirun not found (openmpi-bin)" >&2; exit 1; }
"$bin/frictionSolver" -listModels | grep -q "linear solvers.*mumps" ||
  { echo "parallelBenchmark: this build has no mumps solver (FRICTION_MUMPS)" >&2; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
rm -rf "$work" && mkdir -p "$work/base"

cp -r "$root/cases/pennyCrack" "$work/base/case"
"$work/base/case/Allclean" >/dev/null  # what a run of the case in the source tree left
rm -f "$work/base/case"/log.*
echo "Meshing with gmsh (disc h = $h, growth $slope per unit distance up to $hfar) ..."
(cd "$work/base/case/constant/mesh" &&
  gmsh -3 -format msh41 -setnumber h "$h" -setnumber hFar "$hfar" -setnumber slope "$slope" \
    pennyCrack.geo -o pennyCrack.msh >"$work/gmsh.log" 2>&1)
grep -E '^Info +: [0-9]+ nodes' "$work/gmsh.log" | tail -n 1 | sed 's/^Info *: //'
sed -i 's/^writeVTK.*//; $a writeVTK no;' "$work/base/case/system/controlDict"
"$bin/splitFractureNodes" -case "$work/base/case" >"$work/base/case/log.splitFractureNodes"
grep -E "^ +nodes:" "$work/base/case/log.splitFractureNodes" | head -1 | sed 's/^ */fault /'

wall() {  # wall LOG COMMAND...: run, log to LOG, print the wall seconds
  local log=$1 t0 rc=0
  shift
  t0=$(date +%s.%N)
  "$@" >"$log" 2>&1 || rc=$?
  ((rc == 0)) || { echo "parallelBenchmark: '$*' failed (exit $rc), see $log" >&2; exit 1; }
  awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }'
}
names=(cholmod mumps1)
for n in "${ranks[@]}"; do names+=("mumps$n"); done
declare -A seconds
for name in "${names[@]}"; do
  cp -r "$work/base" "$work/$name"
  dir=$work/$name/case
  solver=mumps
  [[ $name == cholmod ]] && solver=cholmod
  sed -i "s/^linearSolver .*/linearSolver    $solver;/" "$dir/system/frictionSolution"
  case $name in
    cholmod | mumps1) cmd=("$bin/frictionSolver" -case "$dir") ;;
    *) cmd=(mpirun -np "${name#mumps}" "$bin/frictionSolver" -parallel -case "$dir") ;;
  esac
  echo "Running $name ..."
  seconds[$name]=$(wall "$dir/log.frictionSolver" "${cmd[@]}")
done

echo
for name in "${names[@]}"; do
  log=$work/$name/case/log.frictionSolver
  echo "$name (wall ${seconds[$name]} s):"
  grep -E "^(Factorisation|Factor:|Interface operator|Factorisations)" "$log" | sed 's/^/    /'
  grep -E "^Time = " "$log" | cut -c1-120 | sed 's/^/    /'
done
echo
for name in "${names[@]}"; do
  [[ $name == cholmod ]] && continue
  echo "ratio $name / cholmod (wall): $(awk -v a="${seconds[$name]}" -v b="${seconds[cholmod]}" 'BEGIN { printf "%.2f", a / b }')"
done
for n in "${ranks[@]}"; do
  echo "ratio mumps$n / mumps1 (wall): $(awk -v a="${seconds[mumps$n]}" -v b="${seconds[mumps1]}" 'BEGIN { printf "%.2f", a / b }')"
done
echo
dirs=()
for name in "${names[@]}"; do dirs+=("$work/$name/case"); done
/usr/bin/python3 "$root/tests/regression/parallelCompare.py" "${dirs[@]}"
