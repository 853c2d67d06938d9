#!/usr/bin/env bash
# cases/viescaInjection on a coarser mesh (h = 0.1 m): for T = 0.1, 0.5 and 0.9 the slipping
# half-length a(t) of every written time must lie within h/2 + 0.5 % of Viesca (2021)'s
# λ(T) √(4αt) (viescaError.py --check, run by the case's Allrun), and the summary must hold
# every time of the three runs.
# Usage: viescaInjection.sh BIN_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
bin=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
cp -r "$src/cases/viescaInjection" "$work/case"
cd "$work/case"
./Allclean >/dev/null
./Allmesh -h 0.1
FRICTION_BIN=$bin ./Allrun
rows=$(grep -vc '^#' postProcessing/viesca.dat)
[[ $rows == 29 ]] || { echo "FAIL: postProcessing/viesca.dat has $rows rows, expected 29 (9 + 11 + 9 times)"; exit 1; }
echo "PASS: a(t) within h/2 + 0.5 % of lambda(T) sqrt(4 alpha t) at 29 times, T = 0.1, 0.5, 0.9"
