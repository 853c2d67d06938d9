#!/usr/bin/env bash
# The fill-reducing ordering of the factorisation (issue 29, 2D target: the ordering and the
# analysis no more than 20 % of the numeric factorisation). For each mesh, frictionSolver runs
# once per `ordering` of system/frictionSolution (auto, amd, metis, nesdis, cholmodDefault) and
# the log's lines give, all from the same run: the time spent ordering A, the whole ordering
# and analysis (A's ordering, then the analysis of the matrix bordered by the jump unknowns,
# which is what the default run factors), the numeric factorisation, the factor's entries and
# flops, and the mean back-substitution. The ratio analysis / numeric is the target's.
#
# Meshes: 2D, the paperBenchmark square (FreeFEM, n segments per side) at P1 and P2 from about
# 10⁴ to 10⁶ unknowns; 3D, the penny crack (gmsh) at P1, two small sizes (a few minutes).
#
# Usage: orderingBenchmark.sh [BIN_DIR] [WORK_DIR] [SET] [ORDERINGS]
#   SET: all (default), 2d, 3d, quick (2D up to 10⁵ unknowns, a minute) or large (the two 2D
#   meshes of about 10⁶ unknowns, P1 and P2). ORDERINGS: the orderings to run, separated by
#   commas (default: auto,amd,metis,nesdis,cholmodDefault).
# Takes about 15 minutes and 3 GB on 2 cores for `all`; runs one solver at a time.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-$root/build/bin}
work=${2:-$root/build/orderingBenchmark}
set=${3:-all}
case $set in all | 2d | 3d | quick | large) ;; *) echo "orderingBenchmark: SET is all, 2d, 3d, quick or large (got '$set')" >&2; exit 2 ;; esac
for tool in frictionSolver splitFractureNodes; do
  [[ -x "$bin/$tool" ]] || { echo "orderingBenchmark: $bin/$tool not found (build first)" >&2; exit 1; }
done
rm -rf "$work" && mkdir -p "$work"
work=$(cd "$work" && pwd)
IFS=, read -r -a orderings <<<"${4:-auto,amd,metis,nesdis,cholmodDefault}"
for o in "${orderings[@]}"; do
  case $o in auto | amd | metis | nesdis | cholmodDefault) ;; *) echo "orderingBenchmark: unknown ordering '$o'" >&2; exit 2 ;; esac
done

# One row per run: the numbers are read from the log of that run only.
row() { # row LABEL CASE ORDERING
  local log=$2/log.frictionSolver t0 t1
  t0=$(date +%s.%N)
  "$bin/frictionSolver" -case "$2" >"$log" 2>&1 || { echo "frictionSolver failed on $2: $(tail -n 5 "$log")" >&2; exit 1; }
  t1=$(date +%s.%N)
  python3 - "$1" "$3" "$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')" "$log" <<'PY'
import re, sys
label, asked, wall, log = sys.argv[1:]
text = open(log).read()
def num(pattern, default="nan"):
    m = re.search(pattern, text, re.M)
    return m.group(1) if m else default
dofs = num(r"^Setup: finite-element spaces.*?\((\d+) dofs")
orderA = float(num(r"^Setup: ordering and analysis.*?ordering A ([0-9.e+-]+) s"))
factor = re.search(r"^Factor: (\S+) ordering.*?, ([0-9.e+]+) entries.*?, ([0-9.e+]+) flops.*?; "
                   r"([0-9.e+-]+) s ordering and analysis, ([0-9.e+-]+) s numeric", text, re.M)
used, entries, flops, analysis, numeric = factor.groups()
if "AMD then METIS tried" in factor.group(0):
    used += " (AMD tried first)"  # CHOLMOD's strategy ordered twice
solves = re.search(r"^Factorisations .*back-substitutions (\d+) \(([0-9.e+-]+) s\)", text, re.M)
solve = float(solves.group(2)) / int(solves.group(1))
analysis, numeric = float(analysis), float(numeric)
print(f"| {label} | {dofs} | {asked} | {used} | {orderA:.3g} | {analysis:.3g} | {numeric:.3g} | "
      f"{100 * analysis / numeric:.0f} % | {float(entries):.3g} | {float(flops):.3g} | "
      f"{solve:.3g} | {float(wall):.3g} |")
PY
}

header() {
  echo
  echo "| mesh | dofs | ordering | used | ordering A [s] | ordering + analysis [s] | numeric [s] | analysis / numeric | factor entries | flops | solve [s] | run [s] |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
}

square() { # square N P: the paperBenchmark case on the n = N mesh at P<P>, split, in $work
  local c=$work/square-n$1-P$2
  cp -r "$root/cases/paperBenchmark" "$c"
  rm -f "$c"/log.*
  (cd "$c/constant/mesh" &&
    FF_LOADPATH="/usr/lib/freefem++;./" FF_INCLUDEPATH=/usr/include/freefem++/idp \
      FreeFem++ -nw -ns -v 0 square.edp -n "$1" -out square.msh >"$c/log.FreeFem++" 2>&1)
  sed -i "s/^elementOrder .*/elementOrder    $2;/" "$c/system/frictionSolution"
  sed -i '$a writeVTK no;' "$c/system/controlDict"
  "$bin/splitFractureNodes" -case "$c" >"$c/log.splitFractureNodes"
  echo "$c"
}

penny() { # penny H: the penny crack (L = 4a, slope 0.25, hFar L/4) with disc size H, P1
  local c=$work/penny-h$1
  cp -r "$root/cases/pennyCrack" "$c"
  rm -f "$c"/log.*
  (cd "$c/constant/mesh" &&
    gmsh -3 -format msh41 -setnumber h "$1" pennyCrack.geo -o pennyCrack.msh >"$c/log.gmsh" 2>&1)
  sed -i '$a writeVTK no;' "$c/system/controlDict"
  "$bin/splitFractureNodes" -case "$c" >"$c/log.splitFractureNodes"
  echo "$c"
}

sweep() { # sweep LABEL CASE: one run per ordering
  for o in "${orderings[@]}"; do
    sed -i '/^ordering /d' "$2/system/frictionSolution"
    echo "ordering $o;" >>"$2/system/frictionSolution"
    rm -rf "$2/postProcessing" "$2"/[1-9]*
    row "$1" "$2" "$o"
  done
}

if [[ $set != 3d ]]; then
  command -v FreeFem++ >/dev/null || { echo "orderingBenchmark: FreeFem++ not found" >&2; exit 1; }
  # n segments per side: P1 dofs ≈ 2.3 n², P2 dofs ≈ 9 n².
  case $set in
    quick) p1=(66 208) p2=(33 104) ;;
    large) p1=(660) p2=(330) ;;
    *) p1=(66 208 330 660) p2=(33 104 160 330) ;;
  esac
  echo "2D: paperBenchmark square, bordered factor (jump unknowns last)"
  header
  for n in "${p1[@]}"; do c=$(square "$n" 1) && sweep "2D P1 n=$n" "$c"; done
  for n in "${p2[@]}"; do c=$(square "$n" 2) && sweep "2D P2 n=$n" "$c"; done
fi
if [[ $set == all || $set == 3d ]]; then
  command -v gmsh >/dev/null || { echo "orderingBenchmark: gmsh not found" >&2; exit 1; }
  echo
  echo "3D: penny crack, P1, bordered factor (jump unknowns last)"
  header
  # a/16 and a/24 (24 003 and about 50 000 unknowns); a/32 (69 003) took 100 s per run.
  for k in 16 24; do c=$(penny "$(awk -v k="$k" 'BEGIN { print 1 / k }')") && sweep "3D P1 h=a/$k" "$c"; done
fi
