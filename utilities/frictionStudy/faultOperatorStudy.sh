#!/usr/bin/env bash
# What compressing S costs and saves in an earthquake-cycle run (issues #29 and #30):
# cases/seasBP3's 60-degree thrust for YEARS years at each fault cell size h, with the dense S
# (timeIntegration's faultOperator dense, the default) and with S as an H-matrix at each
# tolerance (faultOperator { type hierarchical; tolerance T; }), one run after the other on the
# same mesh. Per run it prints:
#  * kn (the size of S_tt), the share of S's entries the H-matrix stores and its memory, and
#    one product by the H-matrix against one by the dense S, measured in the same run (the
#    log's setup line: alternating, the best of five, so the ratio is of one run on this
#    shared machine);
#  * the whole run: wall time, Runge-Kutta steps and right-hand sides, the mean cost of a
#    right-hand side (a product plus the law's solve at every node plus the fault outputs);
#  * the earthquakes (max slip rate above 1e-3 m/s in global.dat): how many, and the largest
#    shift of an onset [s] and of a peak log10 slip rate against the dense run's.
# Usage: faultOperatorStudy.sh [BIN_DIR] [WORK_DIR] [YEARS] [ORDER] [h ...]
#   (defaults: build/bin, build/faultOperatorStudy, 500 years, P1, h = 200 100 50)
# TOLERANCES="1e-6 1e-8" (the default) chooses the tolerances.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=$(cd "${1:-$root/build/bin}" && pwd)
work=${2:-$root/build/faultOperatorStudy}
years=${3:-500}
order=${4:-1}
shift $(($# < 4 ? $# : 4))
sizes=("$@")
((${#sizes[@]})) || sizes=(200 100 50)
read -r -a tolerances <<<"${TOLERANCES:-1e-6 1e-8}"
mkdir -p "$work"
work=$(cd "$work" && pwd)


printf "%5s %6s %8s %7s %8s %9s %9s %6s %8s %8s %9s %8s %7s %10s %9s\n" h kn operator "stored" MB \
  "prod[us]" "dense[us]" ratio "wall[s]" steps rhs "us/rhs" events "onset[s]" "peak"
for h in "${sizes[@]}"; do
  base=$work/h$h-p$order
  rm -rf "$base"
  cp -r "$root/cases/seasBP3" "$base"
  (cd "$base" && ./Allclean >/dev/null && /usr/bin/python3 bp3Case.py --years "$years" --order "$order" >/dev/null &&
    ./Allmesh -h "$h" >/dev/null && "$bin/splitFractureNodes" -case . >log.splitFractureNodes 2>&1)
  for op in dense "${tolerances[@]}"; do
    c=$work/h$h-p$order-$op
    rm -rf "$c"
    cp -r "$base" "$c"
    if [[ $op != dense ]]; then
      sed -i "s/^timeIntegration { type quasiDynamic;/& faultOperator { type hierarchical; tolerance $op; }/" \
        "$c/system/frictionSolution"
    fi
    start=$(date +%s.%N)
    (cd "$c" && "$bin/frictionSolver" -case . >log.frictionSolver 2>&1) || { echo "h=$h $op: the run failed ($c)"; continue; }
    wall=$(/usr/bin/python3 -c "print($(date +%s.%N) - $start)")
    line=$(grep "^Time integration: [0-9]" "$c/log.frictionSolver")
    steps=$(sed -E 's/^Time integration: ([0-9]+) Runge.*/\1/' <<<"$line")
    rhs=$(sed -E 's/.* ([0-9]+) right-hand sides.*/\1/' <<<"$line")
    perRhs=$(sed -E 's/.*\(([0-9.e+]+) us each.*/\1/' <<<"$line")
    kn=$(sed -E 's/.*S_tt ([0-9]+) x.*/\1/' <<<"$line")
    stored=100 prod=- dense=- ratio=-
    if [[ $op != dense ]]; then
      hline=$(grep -o "H-matrix .*relative difference [0-9.e+-]*" "$c/log.frictionSolver")
      stored=$(sed -E 's/.*; ([0-9.]+) % of the dense.*/\1/' <<<"$hline")
      mb=$(sed -E 's/.*dense entries \(([0-9.]+) MB\).*/\1/' <<<"$hline")
      prod=$(sed -E 's/.*a product ([0-9.e+]+) us against.*/\1/' <<<"$hline")
      dense=$(sed -E "s/.*the dense S's ([0-9.e+]+) us.*/\1/" <<<"$hline")
      ratio=$(sed -E 's/.* us \(([0-9.e+]+)x\).*/\1/' <<<"$hline")
    else
      mb=$(/usr/bin/python3 -c "print($kn * $kn * 2 * 8 / 1048576)")  # S_tt and S_nt (k = 1)
    fi
    read -r _ ea eb _ shift _ peak < <(/usr/bin/python3 -B "$root/cases/seasBP3/bp3Compare.py" \
      "$work/h$h-p$order-dense" "$c" | tail -n 1)
    printf "%5s %6s %8s %6s%% %8.1f %9s %9s %6s %8.0f %8s %9s %8s %7s %10s %9s\n" "$h" "$kn" "$op" "$stored" \
      "$mb" "$prod" "$dense" "$ratio" "$wall" "$steps" "$rhs" "$perRhs" "$eb" "$shift" "$peak"
  done
done
