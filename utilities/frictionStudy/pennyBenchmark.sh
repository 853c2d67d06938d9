#!/usr/bin/env bash
# The cost of friction at scale in 3D (issue 11, "Speed"; issue 29): the penny-shaped crack of
# cases/pennyCrack in a block of about 10⁶ unknowns with more than 2 000 fault nodes. The whole
# frictional solve (Coulomb, semismooth Newton), factorisation included, against one linear
# elastic solve (factorisation plus one back-substitution) of the same mesh without the fault,
# measured in one run and printed as a ratio, with the time of each phase and the peak memory
# of each run. VARIANTS lists the semismoothNewton variants to run, one after the other on the
# same mesh (condensed: the dense S from the factorisation, jump unknowns ordered last;
# krylov: the plain factor, GMRES preconditioned by the probed S; auto: the case's default).
# The last lines are one table of all runs.
#
# Usage: [VARIANTS="condensed krylov"] pennyBenchmark.sh [BIN_DIR] [WORK_DIR] [H HFAR SLOPE]
#   defaults: VARIANTS=condensed, build/bin, build/pennyBenchmark, and the mesh h = a/25 on the
#   disc, growing by 0.05 per unit distance up to 0.135 a (measured in the README, "Speed in 3D").
# Needs about 20 GB of memory and 20 minutes on 2 cores at the default size (README, "Speed");
# a smaller mesh for a try: pennyBenchmark.sh build/bin /tmp/pb 0.0625 0.25 0.25
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-$root/build/bin}
work=${2:-$root/build/pennyBenchmark}
h=${3:-0.04}
hfar=${4:-0.135}
slope=${5:-0.05}
read -r -a variants <<<"${VARIANTS:-condensed}"
((${#variants[@]})) || variants=(condensed)
for v in "${variants[@]}"; do
  [[ $v == condensed || $v == krylov || $v == auto ]] ||
    { echo "pennyBenchmark: VARIANTS: '$v' is not condensed, krylov or auto" >&2; exit 1; }
done
for tool in frictionSolver splitFractureNodes; do
  [[ -x "$bin/$tool" ]] || { echo "pennyBenchmark: $bin/$tool not found (build first)" >&2; exit 1; }
done
command -v gmsh >/dev/null || { echo "pennyBenchmark: gmsh not found" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"

cp -r "$root/cases/pennyCrack" "$work/friction"
rm -f "$work/friction"/log.*
echo "Meshing with gmsh (disc h = $h, growth $slope per unit distance up to $hfar) ..."
t0=$(date +%s.%N)
(cd "$work/friction/constant/mesh" &&
  gmsh -3 -format msh41 -setnumber h "$h" -setnumber hFar "$hfar" -setnumber slope "$slope" \
    pennyCrack.geo -o pennyCrack.msh >"$work/gmsh.log" 2>&1)
tmesh=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.0f", b - a }')
echo "$(grep -E '^Info +: [0-9]+ nodes' "$work/gmsh.log" | tail -n 1 | sed 's/^Info *: //') ($tmesh s)"
sed -i 's/^writeVTK.*//; $a writeVTK no;' "$work/friction/system/controlDict"
cp -r "$work/friction" "$work/linear"
# The linear reference: the same mesh with no fracture (no control loop, one solve).
sed -i 's/^fractures .*/fractures ();/' "$work/linear/system/meshDict"
sed -i '/^fault/,$d' "$work/linear/constant/fractureProperties"

"$bin/splitFractureNodes" -case "$work/friction" >"$work/friction/log.splitFractureNodes"
"$bin/splitFractureNodes" -case "$work/linear" >"$work/linear/log.splitFractureNodes"
grep -E "^ +nodes:" "$work/friction/log.splitFractureNodes" | head -1 | sed 's/^ */fault /'
# d = 3 jump unknowns per split (duplicated) node: the border the condensed variant orders last.
jumps=$(sed -n 's/^ *nodes: *[0-9]* (duplicated \([0-9]*\).*/\1/p' "$work/friction/log.splitFractureNodes" |
  head -n 1 | awk '{ print 3 * $1 }')

# shellcheck source=timedRun.sh
source "$root/utilities/frictionStudy/timedRun.sh"
run() { timedRun "$bin" "$1"; }  # run CASE: wall seconds of frictionSolver
echo "Running the linear solve, then the frictional one with variant ${variants[*]} ..."
tl=$(run "$work/linear")
cp "$work/linear/log.frictionSolver" "$work/log.linear"
declare -A wall
for v in "${variants[@]}"; do
  f=$work/friction/system/frictionSolution
  if [[ $v == auto ]]; then
    sed -i "s/^\( *type *\)semismoothNewton;.*/\1semismoothNewton;/" "$f"
  else
    sed -i "s/^\( *type *\)semismoothNewton;.*/\1semismoothNewton; variant $v;/" "$f"
  fi
  rm -rf "$work/friction"/[1-9]* "$work/friction/postProcessing"
  wall[$v]=$(run "$work/friction")
  cp "$work/friction/log.frictionSolver" "$work/log.$v"
done

summary() {  # summary LOG TITLE
  echo "$2"
  grep -E "^(Split mesh|Factorisation|Factor:|Interface operator|Newton variant|Factorisations)" "$1" |
    sed 's/^/    /'
  grep -E "^Time = " "$1" | sed 's/^/    /'
}
echo
summary "$work/log.linear" "linear elastic solve (wall $tl s):"
for v in "${variants[@]}"; do
  title="frictional solve (wall ${wall[$v]} s):"
  ((${#variants[@]} == 1)) || title="frictional solve, variant $v (wall ${wall[$v]} s):"
  summary "$work/log.$v" "$title"
done
echo
for v in "${variants[@]}"; do
  label="ratio frictional / linear"
  ((${#variants[@]} == 1)) || label="ratio frictional ($v) / linear"
  echo "$label: $(awk -v a="${wall[$v]}" -v b="$tl" 'BEGIN { printf "%.2f", a / b }')  (target <= 1.2)"
done

row() {  # row LOG LABEL WALL: one line of the table, from the log of one run
  local log=$1 factor step nodes tsec products
  factor=$(grep -E "^Factor: " "$log" | head -n 1)
  step=$(grep -E "^Time = " "$log" | head -n 1)
  nodes=$(sed -n 's/^Split mesh: .* \([0-9]*\) fracture control nodes$/\1/p' "$log" | head -n 1)
  num() { sed -n "s/.*[;,] \([0-9.e+-]*\) s $1.*/\1/p" <<<"$factor"; }
  products=$(sed -n 's/.*GMRES products per Newton iteration: \([0-9 ]*\)\].*/\1/p' <<<"$step")
  [[ -z $products ]] || products="$products (sum $(awk '{ s = 0; for (i = 1; i <= NF; ++i) s += $i; print s }' <<<"$products"))"
  tsec=$(sed -n 's/^Factorisations .*back-substitutions \([0-9]*\) (\([0-9.e+-]*\) s).*/\1 (\2 s)/p' "$log")
  printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' "$2" \
    "$nodes" "$( ((nodes > 0)) && echo "$jumps")" \
    "$(sed -n 's/^Factor: .* \([0-9.e+]*\) entries (\([0-9.]*\) GB of values), \([0-9.e+]*\) flops.*/\1 (\2 GB), \3 flops/p' <<<"$factor")" \
    "$(num 'ordering and analysis')" "$(num numeric)" "$(num 'the complement')" \
    "$(sed -n 's/^Time = .*(+\([0-9]*\) building S.*/\1/p' <<<"$step")" \
    "$(sed -n 's/^Time = .*  iterations \([0-9]*\) .*/\1/p' <<<"$step")" \
    "$products" "$tsec" "$3 s" \
    "$(sed -n 's/^Factorisations .*peak memory \([0-9.e+-]*\) GB.*/\1 GB/p' "$log")" \
    "$(awk -v a="$3" -v b="$tl" 'BEGIN { printf "%.2f", a / b }')"
}
echo
echo "| run | fault nodes | jump unknowns | factor: entries (values), flops | ordering and analysis [s] | numeric [s] | complement [s] | set-up solves | Newton iterations | GMRES products per iteration | back-substitutions (time) | wall | peak memory | ratio to linear |"
echo "|---|---:|---:|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|"
row "$work/log.linear" "linear" "$tl"
for v in "${variants[@]}"; do row "$work/log.$v" "$v" "${wall[$v]}"; done
