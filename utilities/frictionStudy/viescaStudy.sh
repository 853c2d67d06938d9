#!/usr/bin/env bash
# What accuracy costs for the injection benchmark (issue: fluid pressure). cases/viescaInjection
# (Viesca 2021: a(t) = lambda(T) sqrt(4 alpha t)) at fault mesh sizes h (default 0.2 0.1 0.05
# 0.025 m), each with the fault pressure from the closed form and computed by diffusion along
# the fault (backward Euler, substeps of 5 ms), for T = 0.1, 0.5, 0.9 at the case's times.
# Prints per run: h, the fault's nodes, the model, T, the largest relative error of a(t)
# (viescaError.py), the wall time of the whole frictionSolver run [s] and its ratio to the
# closed-form run of the same h and T (both measured one after the other, so the ratio is
# what the machine's load cannot distort much).
# Usage: viescaStudy.sh [BIN_DIR] [WORK_DIR] [h ...]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-$root/build/bin}
work=${2:-$root/build/viescaStudy}
shift $(($# < 2 ? $# : 2))
sizes=("$@")
((${#sizes[@]})) || sizes=(0.2 0.1 0.05 0.025)
mkdir -p "$work"
work=$(cd "$work" && pwd)
declare -A times=(
  [0.1]="0.0625 0.125 0.25 0.375 0.5 0.625 0.75 0.875 1"
  [0.5]="0.25 0.5 1 2 3 4 5 6 7 8 9"
  [0.9]="1 2 4 6 9 12 16 20 25"
)
printf "| h [m] | fault nodes | pressure | T | max rel. error of a(t) | wall [s] | ratio to closed form |\n"
printf "|---|---|---|---|---|---|---|\n"
for h in "${sizes[@]}"; do
  base=$work/h$h
  rm -rf "$base"
  cp -r "$root/cases/viescaInjection" "$base"
  (cd "$base" && ./Allclean >/dev/null && ./Allmesh -h "$h" >/dev/null)
  for T in 0.1 0.5 0.9; do
    declare -A wall=()
    for model in closedForm diffusion; do
      d=$base/T$T-$model
      mkdir -p "$d"
      cp -r "$base/0" "$base/constant" "$base/system" "$d"/
      tau0=$(/usr/bin/python3 -c "print(0.6 * 10e6 - $T * 0.6 * 5e6)")
      sed -i "s/stress  (-10e6 -10e6 5.7e6);/stress  (-10e6 -10e6 $tau0);/" "$d/constant/effects"
      [[ $model == diffusion ]] && sed -i \
        's|^    diffusivity 1; .*|    model diffusion; storage 1e-9; transmissivity 1e-9; maxStep 0.005;|' \
        "$d/constant/effects"
      sed -i "/^endTime\|^deltaT\|^writeInterval\|^writeControl/d" "$d/system/controlDict"
      echo "times (${times[$T]});" >>"$d/system/controlDict"
      "$bin/splitFractureNodes" -case "$d" >"$d/log.splitFractureNodes" 2>&1
      start=$(date +%s.%N)
      "$bin/frictionSolver" -case "$d" >"$d/log.frictionSolver" 2>&1
      wall[$model]=$(/usr/bin/python3 -c "print(f'{$(date +%s.%N) - $start:.2f}')")
      err=$(/usr/bin/python3 "$base/viescaError.py" "$d" --T "$T" --alpha 1 | awk '/^maxRelError/{print $2}')
      nodes=$(grep -vc '^#' "$d/$(echo "${times[$T]}" | awk '{print $NF}')/fractures/fault.dat")
      ratio=$(/usr/bin/python3 -c "print(f'{${wall[$model]} / ${wall[closedForm]}:.2f}')")
      printf "| %s | %s | %s | %s | %s | %s | %s |\n" "$h" "$nodes" "$model" "$T" "$err" "${wall[$model]}" "$ratio"
    done
  done
done
