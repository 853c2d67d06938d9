#!/usr/bin/env bash
# Semismooth Newton against the paper's method (issue 14, part 1): the paper benchmark at
# n = 80, P1, 2000 steepest-descent iterations (the paper's alpha 2e-4 diverges on this mesh,
# so the solver's scale-free default step, as in frictionStudy.py) against condensed Newton at
# the loosest tolerance that reaches a smaller slip error (0.03: one iteration; the study
# checks the errors). Runs the two alternately PAIRS times on the same machine state and
# prints, per pair, two ratios measured in that pair:
#   whole: the wall time of the whole frictionSolver process (start-up, reading the split
#          mesh, assembly, factorisation, the step, writing the time folder);
#   solve: factorisation + step, as the log gives them (the "solve" of the GetFEM table).
# Usage: newtonVsSteepest.sh [BIN_DIR] [WORK_DIR] [PAIRS]     (PAIRS: 3)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-$root/build/bin}
work=${2:-$root/build/newtonVsSteepest}
pairs=${3:-3}
rm -rf "$work" && mkdir -p "$work"

cp -r "$root/cases/paperBenchmark" "$work/base"
(cd "$work/base" && ./Allclean >/dev/null 2>&1 || true)
(cd "$work/base" && ./Allmesh -n 80 >/dev/null)
sed -i 's/^writeVTK.*//; $a writeVTK no;' "$work/base/system/controlDict"
setOptimizer() {  # setOptimizer CASE TYPE TOLERANCE MAXITERATIONS
  /usr/bin/python3 - "$@" <<'EOF'
import re, sys
case, kind, tol, iters = sys.argv[1:]
path = case + "/system/frictionSolution"
text = open(path).read()
block = ("optimizer\n    {\n        type %s;\n        tolerance %s;\n        maxIterations %s;\n"
         "    }" % (kind, tol, iters))
text, k = re.subn(r"optimizer\s*\{[^{}]*\}", block, text)
if k != 1:
    sys.exit("newtonVsSteepest: no optimizer block in " + path)
open(path, "w").write(text)
EOF
}
for c in steepest newton; do cp -r "$work/base" "$work/$c"; done
setOptimizer "$work/steepest" steepestDescent 1e-14 2000
setOptimizer "$work/newton" semismoothNewton 0.03 200
for c in steepest newton; do
  "$bin/splitFractureNodes" -case "$work/$c" >"$work/$c/log.splitFractureNodes"
done

# shellcheck source=timedRun.sh
source "$root/utilities/frictionStudy/timedRun.sh"
solveSeconds() {  # factorisation + step seconds from the log
  local log=$1/log.frictionSolver f s
  f=$(sed -n 's/^Factorisations [0-9]* (\([0-9.e-]*\) s).*/\1/p' "$log")
  s=$(sed -n 's/.*\[step 1\/1, \([0-9.e-]*\) s.*/\1/p' "$log")
  awk -v a="$f" -v b="$s" 'BEGIN { printf "%.4f", a + b }'
}
for ((i = 1; i <= pairs; i++)); do
  rm -rf "$work/steepest/1" "$work/steepest/postProcessing"
  ts=$(timedRun "$bin" "$work/steepest")
  rm -rf "$work/newton/1" "$work/newton/postProcessing"
  tn=$(timedRun "$bin" "$work/newton")
  ss=$(solveSeconds "$work/steepest")
  sn=$(solveSeconds "$work/newton")
  echo "pair $i: steepestDescent $ts s (solve $ss s), semismoothNewton $tn s (solve $sn s):" \
    "whole $(awk -v a="$ts" -v b="$tn" 'BEGIN { printf "%.1f", a / b }')x," \
    "solve $(awk -v a="$ss" -v b="$sn" 'BEGIN { printf "%.1f", a / b }')x  (target 50x)"
done
grep -h "^Time = " "$work/steepest/log.frictionSolver" "$work/newton/log.frictionSolver" |
  sed 's/  \[step.*//'
