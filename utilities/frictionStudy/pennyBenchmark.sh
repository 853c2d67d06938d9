#!/usr/bin/env bash
# The cost of friction at scale in 3D (issue 11, "Speed"): the penny-shaped crack of
# cases/pennyCrack in a block of about 10⁶ unknowns with more than 2 000 fault nodes. The whole
# frictional solve (Coulomb, semismooth Newton, condensed), factorisation included, against one
# linear elastic solve (factorisation plus one back-substitution) of the same mesh without the
# fault, measured in one run and printed as a ratio, with the time of each phase and the peak
# memory of each run.
#
# Usage: pennyBenchmark.sh [BIN_DIR] [WORK_DIR] [H HFAR SLOPE]
#   defaults: build/bin, build/pennyBenchmark, and the mesh h = a/25 on the disc, growing by
#   0.05 per unit distance up to 0.135 a (measured in the README, "Speed in 3D").
# Needs about 20 GB of memory and 20 minutes on 2 cores at the default size (README, "Speed");
# a smaller mesh for a try: pennyBenchmark.sh build/bin /tmp/pb 0.0625 0.25 0.25
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-$root/build/bin}
work=${2:-$root/build/pennyBenchmark}
h=${3:-0.04}
hfar=${4:-0.135}
slope=${5:-0.05}
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

# shellcheck source=timedRun.sh
source "$root/utilities/frictionStudy/timedRun.sh"
run() { timedRun "$bin" "$1"; }  # run CASE: wall seconds of frictionSolver
echo "Running the linear solve, then the frictional one ..."
tl=$(run "$work/linear")
tf=$(run "$work/friction")

summary() {  # summary CASE TITLE
  local log=$1/log.frictionSolver
  echo "$2"
  grep -E "^(Split mesh|Factorisation|Factor:|Interface operator|Factorisations)" "$log" | sed 's/^/    /'
  grep -E "^Time = " "$log" | sed 's/^/    /'
}
echo
summary "$work/linear" "linear elastic solve (wall $tl s):"
summary "$work/friction" "frictional solve (wall $tf s):"
echo
echo "ratio frictional / linear: $(awk -v a="$tf" -v b="$tl" 'BEGIN { printf "%.2f", a / b }')  (target <= 2)"
