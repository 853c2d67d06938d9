#!/usr/bin/env bash
# What accuracy costs at junctions (issue: fracture networks). The T (a branch at 120°
# ending on the main fracture) and the X (two fractures crossing at 90°) of
# tests/regression/cases/junctions, P1 and P2, fracture mesh size h = 0.1, 0.05, 0.025,
# 0.0125 m (far size 10 h), semismooth Newton (condensed) to 1e-12, one step.
# Prints per run the fracture control nodes, Newton iterations, the wall time of the whole
# frictionSolver run, the main fracture's slip norm ‖s‖ (L², trapezoid over s) and its
# relative difference from the finest P2 run's (the reference: the error of the others, up
# to the reference's own, which Richardson puts below 0.5 %), then per order the time ratios
# to that order's coarsest run. The runs are timed in one session, one after another.
# Usage: junctionStudy.sh [BIN_DIR] [WORK_DIR]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-$root/build/bin}
work=${2:-$root/build/junctionStudy}
# shellcheck source=timedRun.sh
source "$root/utilities/frictionStudy/timedRun.sh"
command -v gmsh >/dev/null || { echo "gmsh not found (Debian package gmsh)" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"

slipNorm() {  # slipNorm TABLE: the L² norm of the slip column over s
  awk '!/^#/ { s[n] = $1; v[n] = $4; n++ }
       END { for (i = 0; i + 1 < n; i++) t += (s[i+1] - s[i]) * (v[i]^2 + v[i+1]^2) / 2;
             printf "%.10e", sqrt(t) }' "$1"
}

results=$work/results.txt
: >"$results"
for kind in T X; do
  case $kind in
    T) opts=(-setnumber branch 1 -setnumber theta 120) ;;
    X) opts=(-setnumber branch 2 -setnumber theta 90) ;;
  esac
  for order in 1 2; do
    for h in 0.1 0.05 0.025 0.0125; do
      c=$work/$kind-P$order-h$h
      cp -r "$root/tests/regression/cases/junctions" "$c"
      "$c/Allclean" >/dev/null
      sed -i "s/^elementOrder .*/elementOrder    $order;/" "$c/system/frictionSolution"
      printf 'writeVTK no;\n' >>"$c/system/controlDict"
      hFar=$(awk -v h="$h" 'BEGIN { print 10 * h }')
      gmsh -2 -format msh41 "${opts[@]}" -setnumber h "$h" -setnumber hFar "$hFar" \
        "$c/constant/mesh/junctions.geo" -o "$c/constant/mesh/junctions.msh" >"$c/log.gmsh" 2>&1
      "$bin/splitFractureNodes" -case "$c" >"$c/log.splitFractureNodes" 2>&1
      t=$(timedRun "$bin" "$c")
      nodes=$(grep -o '[0-9]* fracture control nodes' "$c/log.frictionSolver" | cut -d' ' -f1)
      its=$(grep -o '^Time = 1  iterations [0-9]*' "$c/log.frictionSolver" | awk '{ print $5 }')
      grep -q ' converged' "$c/log.frictionSolver" || { echo "$c: not converged" >&2; exit 1; }
      echo "$kind $order $h $nodes $its $t $(slipNorm "$c/1/fractures/main.dat")" >>"$results"
    done
  done
done

echo "| junction | order | h [m] | control nodes | Newton iterations | time [s] | ‖s_main‖ [m²ᐟ²] | difference from P2, h = 0.0125 |"
echo "|---|---|---|---|---|---|---|---|"
awk '{ key = $1; row[NR] = $0; if ($2 == 2 && $3 == 0.0125) ref[key] = $7 }
     END { for (i = 1; i <= NR; i++) { split(row[i], f, " ");
             diff = f[7] > ref[f[1]] ? f[7] - ref[f[1]] : ref[f[1]] - f[7];
             d = sprintf("%.2f %%", 100 * diff / ref[f[1]]);
             if (f[2] == 2 && f[3] == 0.0125) d = "(reference)";
             printf "| %s | P%s | %s | %s | %s | %s | %.5e | %s |\n", f[1], f[2], f[3], f[4], f[5], f[6], f[7], d } }' "$results"
echo
echo "Time ratios to the coarsest run of the same junction and order (one session):"
awk '{ key = $1 " P" $2; if (!(key in first)) { first[key] = $6; order[++n] = key }
       line[key] = line[key] sprintf(" %s", ($6 > 0 ? sprintf("%.1f", $6 / first[key]) : "-")) }
     END { for (i = 1; i <= n; i++) print "  " order[i] ":" line[order[i]] }' "$results"
