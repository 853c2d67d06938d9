#!/usr/bin/env bash
# What accuracy costs for the injection benchmark (issue: fluid pressure). cases/viescaInjection
# (Viesca 2021: a(t) = lambda(T) sqrt(4 alpha t)) at fault mesh sizes h (default 0.2 0.1 0.05
# 0.025 m), each with the fault pressure from the closed form and computed by diffusion along
# the fault (backward Euler, substeps of 5 ms), for T = 0.1, 0.5, 0.9 at the case's times.
# Prints per run: h, the fault's nodes, the model, T, the largest relative error of a(t) and
# the largest relative errors of the slip profile (max norm and L2, over the written times;
# viescaError.py against viescaSlip.py), the wall time of the whole frictionSolver run [s] and
# its ratio to the closed-form run of the same h and T (both measured one after the other, so
# the ratio is what the machine's load cannot distort much).
# A size may be written h:hFar to set the far-field mesh size too (default 6 m), e.g.
# 0.1:3 0.05:1.5 for a refinement of the whole mesh; MODELS="closedForm" skips the diffusion.
# Usage: [MODELS="closedForm diffusion"] viescaStudy.sh [BIN_DIR] [WORK_DIR] [h[:hFar] ...]
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
read -r -a models <<<"${MODELS:-closedForm diffusion}"
printf "| h [m] | hFar [m] | fault nodes | pressure | T | max rel. error of a(t) | slip: max error | slip: L2 error | wall [s] | ratio to closed form |\n"
printf "|---|---|---|---|---|---|---|---|---|---|\n"
for size in "${sizes[@]}"; do
  h=${size%%:*} hFar=6
  [[ $size == *:* ]] && hFar=${size#*:}
  base=$work/h$h-$hFar
  rm -rf "$base"
  cp -r "$root/cases/viescaInjection" "$base"
  (cd "$base" && ./Allclean >/dev/null && ./Allmesh -h "$h" -hFar "$hFar" >/dev/null)
  for T in 0.1 0.5 0.9; do
    declare -A wall=()
    for model in "${models[@]}"; do
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
      read -r err slipMax slipL2 < <(/usr/bin/python3 "$base/viescaError.py" "$d" --T "$T" --alpha 1 |
        awk '/^maxRelError/{a=$2} /^maxSlipError/{m=$2} /^maxSlipL2Error/{l=$2} END{print a, m, l}')
      nodes=$(grep -vc '^#' "$d/$(echo "${times[$T]}" | awk '{print $NF}')/fractures/fault.dat")
      ratio=-
      [[ -n ${wall[closedForm]:-} ]] &&
        ratio=$(/usr/bin/python3 -c "print(f'{${wall[$model]} / ${wall[closedForm]}:.2f}')")
      printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n" "$h" "$hFar" "$nodes" "$model" "$T" "$err" \
        "$slipMax" "$slipL2" "${wall[$model]}" "$ratio"
    done
  done
done
