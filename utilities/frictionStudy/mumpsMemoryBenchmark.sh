#!/usr/bin/env bash
# How large a 3D model fits (issue 29, "3D volume"): the penny crack of cases/pennyCrack, meshed
# as pennyBenchmark.sh meshes it, solved with linearSolver mumps full rank, block low-rank
# (lowRank ε) and out of core (outOfCore yes), one run each, one after the other. Printed per
# run, from its log: MUMPS's factor entries (the low-rank ones against the full-rank count,
# INFOG(35) / INFOG(29)), the memory MUMPS's factorisation took (INFOG(21)), what it wrote to
# disk (RINFOG(16)), the peak resident memory of the process, the factorisation's and the run's
# wall time, Newton's iterations, and the error of the slip (and of the tractions) against the
# full-rank in-core run, as a fraction of the largest slip (traction) of the fault; with the
# ratios to the full-rank in-core run.
#
# Usage: mumpsMemoryBenchmark.sh [BIN_DIR] [WORK_DIR] [H HFAR SLOPE]
#   defaults: build/bin, build/mumpsMemoryBenchmark, and pennyBenchmark.sh's small mesh
#   0.0625 0.25 0.25 (76 773 unknowns, ~2 GB, a few minutes); 0.04 0.135 0.05 is the 678 102-
#   unknown mesh of README "Speed in 3D" (needs ~20 GB in core and an hour or more).
#   VARIANTS (environment): the runs, in order, among full, ooc, blr<ε>, blr<ε>ooc, cholmod;
#   default "full ooc blr1e-10 blr1e-8 blr1e-6 blr1e-10ooc blr1e-8ooc blr1e-6ooc". The first
#   full or ooc run (the same factor, in memory or on disk: the same slip to the last digit) is
#   the reference of the errors and ratios (without one, errors are not printed).
#   LIMIT (environment): seconds after which a run is stopped (default 6000).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-$root/build/bin}
work=${2:-$root/build/mumpsMemoryBenchmark}
h=${3:-0.0625}
hfar=${4:-0.25}
slope=${5:-0.25}
variants=${VARIANTS:-full ooc blr1e-10 blr1e-8 blr1e-6 blr1e-10ooc blr1e-8ooc blr1e-6ooc}
limit=${LIMIT:-6000}
for tool in frictionSolver splitFractureNodes; do
  [[ -x "$bin/$tool" ]] || { echo "mumpsMemoryBenchmark: $bin/$tool not found (build first)" >&2; exit 1; }
done
"$bin/frictionSolver" -listModels | grep -q "linear solvers.*mumps" ||
  { echo "mumpsMemoryBenchmark: this build has no mumps (FRICTION_MUMPS)" >&2; exit 1; }
command -v gmsh >/dev/null || { echo "mumpsMemoryBenchmark: gmsh not found" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"

cp -r "$root/cases/pennyCrack" "$work/base"
rm -rf "$work/base"/log.* "$work/base/constant/splitMesh"
echo "Meshing with gmsh (disc h = $h, growth $slope per unit distance up to $hfar) ..."
(cd "$work/base/constant/mesh" &&
  gmsh -3 -format msh41 -setnumber h "$h" -setnumber hFar "$hfar" -setnumber slope "$slope" \
    pennyCrack.geo -o pennyCrack.msh >"$work/gmsh.log" 2>&1)
grep -E '^Info +: [0-9]+ nodes' "$work/gmsh.log" | tail -n 1 | sed 's/^Info *: //'
sed -i 's/^writeVTK.*//; $a writeVTK no;' "$work/base/system/controlDict"
"$bin/splitFractureNodes" -case "$work/base" >"$work/base/log.splitFractureNodes"

keysOf() {  # keysOf VARIANT: the line that replaces linearSolver in system/frictionSolution
  local v=$1 keys="linearSolver mumps;"
  [[ $v == cholmod ]] && { echo "linearSolver cholmod;"; return; }
  [[ $v == *ooc ]] && keys+=" outOfCore yes;"
  v=${v%ooc}
  [[ $v == blr* ]] && keys+=" lowRank ${v#blr};"
  echo "$keys"
}
field() {  # field LOG SED_EXPRESSION: the first match, or -
  local x
  x=$(sed -n "$2" "$1" | head -n 1)
  echo "${x:--}"
}
errors() {  # errors REFERENCE RUN: largest slip and traction differences, relative
  python3 - "$1" "$2" <<'EOF'
import glob, os, sys
def table(path):
    head, rows = None, []
    for line in open(path):
        if line.startswith("#"):
            head = head or line[1:].split()
        elif line.strip():
            rows.append(line.split())
    return head, rows
worst = {"slip": 0.0, "traction": 0.0}
for ref in glob.glob(os.path.join(sys.argv[1], "*", "fractures", "*.dat")):
    h, a = table(ref)
    _, b = table(os.path.join(sys.argv[2], os.path.relpath(ref, sys.argv[1])))
    for kind, cols in (("slip", [c for c in h if c.startswith("slip")]),
                       ("traction", [c for c in h if c == "sigmaN" or c.startswith("tau")])):
        idx = [h.index(c) for c in cols]
        scale = max(abs(float(r[i])) for r in a for i in idx) or 1.0
        worst[kind] = max([worst[kind]] + [abs(float(x[i]) - float(y[i])) / scale
                                           for x, y in zip(a, b) for i in idx])
print(f"{worst['slip']:.2g} {worst['traction']:.2g}")
EOF
}

printf '\n%-13s %9s %9s %7s %8s %8s %8s %8s %8s %5s %9s %9s\n' run entries "fullRank" share \
  "MUMPS GB" "disk GB" "peak GB" "factor s" "wall s" iters "slip err" "tract err"
ref=
declare -A peak wall
for v in $variants; do
  c=$work/$v
  mkdir -p "$c"
  cp -r "$work/base/0" "$work/base/system" "$c/"
  mkdir -p "$c/constant" && cp -r "$work/base/constant"/* "$c/constant/"
  sed -i "s|^linearSolver .*|$(keysOf "$v")|" "$c/system/frictionSolution"
  free -g | awk '/^Mem:/ { printf "(%s: %s GB available before the run)\n", "'"$v"'", $7 }' >&2
  t0=$(date +%s.%N)
  rc=0
  timeout "$limit" "$bin/frictionSolver" -case "$c" >"$c/log.frictionSolver" 2>&1 || rc=$?
  t=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  log=$c/log.frictionSolver
  if ((rc != 0)); then
    printf '%-13s failed (exit %s after %s s): %s\n' "$v" "$rc" "$t" \
      "$(grep -a "error" "$log" | tail -n 1 | cut -c1-120)"
    continue
  fi
  if [[ $v == blr* ]]; then
    entries=$(field "$log" 's/^Low-rank factor (BLR, dropping tolerance [^)]*): \([0-9.e+]*\) entries.*/\1/p')
    full=$(field "$log" 's/^Low-rank factor .* entries of the full-rank \([0-9.e+]*\) .*/\1/p')
  else
    entries=$(field "$log" 's/^Factor: .*ordering, \([0-9.e+]*\) entries.*/\1/p')
    full=$entries
  fi
  share=$(awk -v a="$entries" -v b="$full" 'BEGIN { printf "%.1f%%", 100 * a / b }')
  mumpsGb=$(field "$log" 's/^Factor: .* rank, \([0-9.e+-]*\) GB on the largest rank.*/\1/p')
  disk=$(field "$log" 's/^Out-of-core factor: \([0-9.e+-]*\) GB written.*/\1/p')
  peak[$v]=$(field "$log" 's/.*peak memory \([0-9.e+-]*\) GB.*/\1/p')
  factor=$(field "$log" 's/^Factorisation: ok ([a-z]*, \([0-9.e+-]*\) s).*/\1/p')
  iters=$(field "$log" 's/^Time = [^ ]*  iterations \([0-9]*\).*/\1/p')
  wall[$v]=$t
  err="- -"
  if [[ -z $ref && ($v == full || $v == ooc) ]]; then
    ref=$v
    err="(ref) (ref)"
  elif [[ -n $ref ]]; then
    err=$(errors "$work/$ref" "$c")
  fi
  # shellcheck disable=SC2086
  printf '%-13s %9s %9s %7s %8s %8s %8s %8s %8s %5s %9s %9s\n' "$v" "$entries" "$full" "$share" \
    "$mumpsGb" "$disk" "${peak[$v]}" "$factor" "$t" "$iters" $err
  # The run's outputs are not needed for the next: keep the log and the tables.
  rm -rf "$c/constant"
done
if [[ -n $ref ]]; then
  echo
  echo "ratios to the $ref run (peak memory, wall):"
  for v in $variants; do
    [[ -n ${peak[$v]:-} && $v != "$ref" ]] || continue
    awk -v v="$v" -v p="${peak[$v]}" -v P="${peak[$ref]}" -v w="${wall[$v]}" -v W="${wall[$ref]}" \
      'BEGIN { printf "  %-13s %.2f  %.2f\n", v, p / P, w / W }'
  done
fi
