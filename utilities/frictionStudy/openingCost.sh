#!/usr/bin/env bash
# What opening costs (issue: fractures that open). cases/sneddonCrack on one mesh, solved with
# contact unilateral and with contact bilateral, the same loads, semismoothNewton condensed
# to 1e-10:
#   sneddon   the fluid pressure 1 MPa alone: unilateral opens the whole crack (Sneddon);
#             bilateral holds the faces shut (nothing to iterate on: the trial state is the
#             answer);
#   partly    a hat pressure (0.2 MPa at the tips, 1 MPa at the centre) under σ_yy = −0.8 MPa
#             and a shear 0.3 MPa: unilateral opens the middle and slides the ends;
#             bilateral slides the whole crack.
# Prints per run the Newton iterations, the step's back-substitutions, its node states, the
# time of the step (the log's: S, the Newton iterations, the final primal solve and the
# writing) and the wall time of the whole frictionSolver run, then unilateral/bilateral
# ratios of the wall time. The runs of a pair follow each other.
# Usage: openingCost.sh [BIN_DIR] [WORK_DIR] [H] [ORDER]   (default H = 0.015625 = a/64, P2)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-$root/build/bin}
work=${2:-$root/build/openingCost}
h=${3:-0.015625}
order=${4:-2}
# shellcheck source=timedRun.sh
source "$root/utilities/frictionStudy/timedRun.sh"
rm -rf "$work" && mkdir -p "$work"
base=$work/base
cp -r "$root/cases/sneddonCrack" "$base"
"$base/Allclean" >/dev/null
"$base/Allmesh" -h "$h" >/dev/null
sed -i "s/^elementOrder .*/elementOrder $order;/" "$base/system/frictionSolution"
sed -i 's/^writeVTK.*//; $a writeVTK no;' "$base/system/controlDict"
"$bin/splitFractureNodes" -case "$base" >"$base/log.splitFractureNodes"

effects() {  # effects CASE SCENARIO
  local head='FoamFile { version 2.0; format ascii; class dictionary; object effects; }'
  case $2 in
    sneddon) printf '%s\nfluid { type fracturePressure; fracture crack; pressure 1e6; }\n' "$head" ;;
    partly)
      printf '0 2e5\n1 1e6\n2 2e5\n' >"$1/constant/p.dat"
      printf '%s\nfluid { type fracturePressure; fracture crack; values "constant/p.dat"; }\n' "$head"
      printf 'inSitu { type initialStress; stress (-0.3e6 -0.8e6 0.3e6); }\n' ;;
  esac >"$1/constant/effects"
}
field() { sed -n "s/^Time = .*  $2 \([0-9.e+-]*\).*/\1/p" "$1" | head -n 1; }

echo "cases/sneddonCrack, h = $h m (a = 1 m), P$order"
printf '| scenario | contact | Newton iterations | back-subst. | states | step [s] | wall [s] |\n|---|---|---:|---:|---|---:|---:|\n'
declare -A wall
for scenario in sneddon partly; do
  for contact in unilateral bilateral; do
    c=$work/$scenario-$contact
    cp -r "$base" "$c"
    effects "$c" "$scenario"
    sed -i "s/contact .*unilateral;.*/contact $contact;/" "$c/constant/fractureProperties"
    t=$(timedRun "$bin" "$c")
    wall[$scenario-$contact]=$t
    log=$c/log.frictionSolver
    states=$(sed -n 's/.*nodes \(stick [0-9]* slip [0-9]* open [0-9]* tip [0-9]*\).*/\1/p' "$log" | head -n 1)
    if [[ -z $states ]]; then
      states=$(awk '!/^#/ {n[$NF]++} END {printf "stick %d slip %d open %d tip %d", n["stick"], n["slip"], n["open"], n["tip"]}' "$c/1/fractures/crack.dat")
    fi
    step=$(sed -n 's/^Time = .*\[step 1\/1, \([0-9.e+-]*\) s.*/\1/p' "$log" | head -n 1)
    printf '| %s | %s | %s | %s | %s | %s | %s |\n' "$scenario" "$contact" "$(field "$log" iterations)" \
      "$(field "$log" backSubstitutions)" "$states" "$step" "$t"
  done
done
sed -n 's/^Split mesh: .*, \([0-9]*\) fracture control nodes/crack control nodes: \1/p' \
  "$work/sneddon-unilateral/log.frictionSolver"
for scenario in sneddon partly; do
  awk -v s="$scenario" -v u="${wall[$scenario-unilateral]}" -v b="${wall[$scenario-bilateral]}" \
    'BEGIN { printf "%s: unilateral / bilateral wall time %.2f\n", s, u / b }'
done
