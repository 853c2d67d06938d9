#!/usr/bin/env bash
# cases/strikeSlipFaultFreeFem (the plug-in's 3D example) on a coarse mesh, from its Allrun:
# FreeFem++ ends normally, frictionSolve returns 0, and the table the script got back
# (postProcessing/freefemFault.dat, full precision) equals the fault's table the same run wrote
# in 8/fractures/fault.dat (writePrecision digits: relative 1e-6 of each column's largest
# value is ample), row by row with the state codes; the folder holds the eight time folders.
# Usage: freefemExample3d.sh BIN_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
bin=$(cd "$1" && pwd) src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
cp -r "$src/cases/strikeSlipFaultFreeFem" "$work/case"
cd "$work/case"
./Allclean >/dev/null
FRICTION_BIN=$bin ./Allrun -nFault 8 -nSide 6 -nLayers 4 | tee log.allrun
grep -q "^frictionSolve: exit status 0," log.allrun || { echo "FAIL: frictionSolve did not return 0"; exit 1; }
n=$(ls -d [1-9]* | wc -l)
[[ $n == 8 ]] || { echo "FAIL: $n time folders, expected 8"; exit 1; }
/usr/bin/python3 - postProcessing/freefemFault.dat 8/fractures/fault.dat <<'PY'
import math, sys
got = [list(map(float, l.split())) for l in open(sys.argv[1]) if l.strip()]
lines = open(sys.argv[2]).read().splitlines()
header = lines[0][1:].split()
rows = [l.split() for l in lines if not l.startswith("#")]
codes = {"stick": 0, "slip": 1, "open": 2, "tip": 3}
assert len(got) == len(rows) > 10, (len(got), len(rows))
assert all(len(g) == len(header) for g in got), (len(got[0]), len(header))
scale = [max(abs(float(r[j])) for r in rows if math.isfinite(float(r[j]))) or 1.0
         for j in range(len(header) - 1)]
for g, r in zip(got, rows):
    for j in range(len(header) - 1):
        a, b = g[j], float(r[j])
        assert (math.isnan(a) and math.isnan(b)) or abs(a - b) <= 1e-6 * scale[j], (header[j], a, b)
    assert g[-1] == codes[r[-1]], (g[-1], r[-1])
print(f"PASS: the script's table equals 8/fractures/fault.dat ({len(rows)} rows, {len(header)} columns)")
PY
