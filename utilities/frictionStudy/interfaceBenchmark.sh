#!/usr/bin/env bash
# What the interface operator costs (issue: speed at scale, part 1). The inclined crack with
# half-length a = 0.2 m and 2N+1 crack nodes (h = a/N, a band of 8h at size h, graded to
# 0.02 m; with the case's a = 0.05 gmsh 4.11 leaves zero-area triangles on the crack from
# h ≈ 2e-5 m on, which splitFractureNodes refuses), for each N: one
# linear elastic solve of the same mesh without the crack, then the frictional solve with
# semismoothNewton condensed, S formed
#   factorisation  from the one factorisation (Schur complement of the bordered matrix),
#   blockSolves    from blocks of 64 right-hand sides with the factor,
#   dualSolves     one dual solve per crack node (the way before),
# (these two are skipped above 2 100 nodes, where they take many minutes, and with
# KRYLOV_ONLY=1) and with the krylov variant under each preconditioner of its GMRES (none,
# blockDiagonal, probing: GMRES products per Newton iteration and the set-up solves that
# probe S, second table). Then the same krylov rows in 3D: the penny crack of cases/pennyCrack
# at each disc mesh size of PENNY_H (default 0.125 = a/8, the committed mesh; empty: none),
# against the linear solve of its mesh without the fault. All runs of one size follow each
# other on the same machine state; the ratios to the linear solve are printed as measured
# (wall time of the whole frictionSolver run, reading the split mesh included).
# Usage: [KRYLOV_ONLY=1] [PENNY_H="0.125 0.0625"] interfaceBenchmark.sh [BIN_DIR] [WORK_DIR] [N ...]
#        (default N: 64 256 1024)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-$root/build/bin}
work=${2:-$root/build/interfaceBenchmark}
shift $(($# < 2 ? $# : 2))
sizes=("$@")
((${#sizes[@]})) || sizes=(64 256 1024)
mkdir -p "$work"
work=$(cd "$work" && pwd)  # absolute: the meshing runs in the case's mesh folder

wall() {  # wall CASE: seconds of frictionSolver on CASE (its log in CASE/log.frictionSolver)
  local t0 t1
  rm -rf "$1"/[1-9]* "$1/postProcessing" "$1/VTK"
  t0=$(date +%s.%N)
  "$bin/frictionSolver" -case "$1" >"$1/log.frictionSolver" 2>&1 || true
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }'
}
field() {  # field LOG KEY: the number after KEY on the step line
  sed -n "s/^Time = .*  $2 \([0-9.e+-]*\).*/\1/p" "$1" | head -n 1
}
status() {  # status LOG: the first step's status
  grep -o -E '(converged|maxIterations|stalled|diverged|inaccurate)  ' "$1" | head -n 1 | tr -d ' '
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }

krylovTable="| case | crack nodes | unknowns | linear solve | preconditioner | Newton iterations | GMRES products per iteration | set-up solves | frictional solve | ratio to linear |
|---|---:|---:|---:|---|---:|---|---:|---:|---:|"
krylovRows() {  # krylovRows LABEL CASE LINEAR_SECONDS: the krylov variant under each preconditioner
  local f=$2/system/frictionSolution pre tf log products mean
  for pre in none blockDiagonal probing; do
    sed -i "s/^\( *type *\)semismoothNewton;.*/\1semismoothNewton; variant krylov; preconditioner $pre;/" "$f"
    tf=$(wall "$2")
    log=$2/log.frictionSolver
    cp "$log" "$(dirname "$2")/log.krylov-$pre"
    products=$(sed -n 's/^Time = .*GMRES products per Newton iteration: \([0-9 ]*\)\].*/\1/p' "$log" | head -n 1)
    mean=$(echo "$products" | awk '{ s = 0; for (i = 1; i <= NF; ++i) s += $i; if (NF) printf "%.0f", s / NF }')
    krylovTable+=$'\n'"| $1 | $(sed -n 's/.* \([0-9]*\) fracture control nodes.*/\1/p' "$log") | $(sed -n 's/.* \([0-9]*\) dofs (P[12]).*/\1/p' "$log") | $3 s | $pre | $(field "$log" iterations) | $products (mean $mean) | $(sed -n 's/^Time = .*(+\([0-9]*\) building S.*/\1/p' "$log" | head -n 1) | $tf s ($(status "$log")) | $(ratio "$tf" "$3") |"
  done
  sed -i "s/^\( *type *\)semismoothNewton;.*/\1semismoothNewton;/" "$f"
}

table="| crack nodes | unknowns | linear solve | S formed by | Newton iterations | back-subst. (step + S) | frictional solve | ratio to linear |
|---:|---:|---:|---|---:|---:|---:|---:|"
for N in "${sizes[@]}"; do
  h=$(awk -v n="$N" 'BEGIN { printf "%.12g", 0.2 / n }')
  dmin=$(awk -v h="$h" 'BEGIN { printf "%.12g", 8 * h }')
  c=$work/N$N
  rm -rf "$c" && mkdir -p "$c"
  cp -r "$root/cases/inclinedCrack" "$c/friction"
  rm -f "$c/friction"/log.*
  echo "N = $N: meshing (h = $h m) ..." >&2
  (cd "$c/friction/constant/mesh" &&
    gmsh -2 -format msh41 -setnumber a 0.2 -setnumber h "$h" -setnumber dMin "$dmin" -setnumber hFar 0.02 \
      inclinedCrack.geo -o inclinedCrack.msh >"$c/gmsh.log" 2>&1)
  sed -i 's/^writeVTK.*//; $a writeVTK no;' "$c/friction/system/controlDict"
  cp -r "$c/friction" "$c/linear"
  sed -i 's/^fractures .*/fractures ();/' "$c/linear/system/meshDict"
  sed -i '/^crack/,$d' "$c/linear/constant/fractureProperties"
  "$bin/splitFractureNodes" -case "$c/friction" >"$c/friction/log.splitFractureNodes"
  "$bin/splitFractureNodes" -case "$c/linear" >"$c/linear/log.splitFractureNodes"

  tl=$(wall "$c/linear")
  nodes=$(sed -n 's/.* \([0-9]*\) fracture control nodes.*/\1/p' "$c/friction/log.frictionSolver" 2>/dev/null || true)
  for how in factorisation blockSolves dualSolves; do
    f=$c/friction/system/frictionSolution
    sed -i "s/^\( *type *\)semismoothNewton;.*/\1semismoothNewton; interfaceOperator $how;/" "$f"
    if [[ $how == dualSolves || $how == blockSolves ]] && { ((2 * N + 1 > 2100)) || [[ ${KRYLOV_ONLY:-} == 1 ]]; }; then
      table+=$'\n'"| $((2 * N + 1)) | | | $how | | | skipped | |"
      continue
    fi
    tf=$(wall "$c/friction")
    log=$c/friction/log.frictionSolver
    cp "$log" "$c/log.$how"
    dofs=$(sed -n 's/.* \([0-9]*\) dofs (P1).*/\1/p' "$log")
    nodes=$(sed -n 's/.* \([0-9]*\) fracture control nodes.*/\1/p' "$log")
    it=$(field "$log" iterations)
    bs=$(field "$log" backSubstitutions)
    setup=$(sed -n 's/^Time = .*(+\([0-9]*\) building S.*/\1/p' "$log" | head -n 1)
    table+=$'\n'"| $nodes | $dofs | $tl s | $how | $it | $bs + ${setup:-0} | $tf s ($(status "$log")) | $(ratio "$tf" "$tl") |"
  done
  sed -i "s/^\( *type *\)semismoothNewton;.*/\1semismoothNewton;/" "$c/friction/system/frictionSolution"
  krylovRows "inclined crack" "$c/friction" "$tl"
done

for H in ${PENNY_H-0.125}; do
  c=$work/penny$H
  rm -rf "$c" && mkdir -p "$c"
  cp -r "$root/cases/pennyCrack" "$c/friction"
  rm -f "$c/friction"/log.*
  echo "penny crack: meshing (disc h = $H a) ..." >&2
  (cd "$c/friction/constant/mesh" &&
    gmsh -3 -format msh41 -setnumber h "$H" pennyCrack.geo -o pennyCrack.msh >"$c/gmsh.log" 2>&1)
  sed -i 's/^writeVTK.*//; $a writeVTK no;' "$c/friction/system/controlDict"
  cp -r "$c/friction" "$c/linear"
  sed -i 's/^fractures .*/fractures ();/' "$c/linear/system/meshDict"
  sed -i '/^fault/,$d' "$c/linear/constant/fractureProperties"
  "$bin/splitFractureNodes" -case "$c/friction" >"$c/friction/log.splitFractureNodes"
  "$bin/splitFractureNodes" -case "$c/linear" >"$c/linear/log.splitFractureNodes"
  tl=$(wall "$c/linear")
  # condensed, S from the factorisation: the reference (named: the default, auto, may take krylov)
  sed -i "s/^\( *type *\)semismoothNewton;.*/\1semismoothNewton; variant condensed;/" "$c/friction/system/frictionSolution"
  tf=$(wall "$c/friction")
  cp "$c/friction/log.frictionSolver" "$c/log.factorisation"
  krylovTable+=$'\n'"| penny a/$(awk -v h="$H" 'BEGIN { printf "%g", 1 / h }') | | | $tl s | (condensed, S from the factorisation) | $(field "$c/log.factorisation" iterations) | | | $tf s ($(status "$c/log.factorisation")) | $(ratio "$tf" "$tl") |"
  krylovRows "penny a/$(awk -v h="$H" 'BEGIN { printf "%g", 1 / h }')" "$c/friction" "$tl"
done
echo
echo "$table"
echo
echo "$krylovTable"
