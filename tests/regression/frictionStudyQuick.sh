#!/usr/bin/env bash
# Benchmark (ctest label "long", not a test of correctness): runs
# utilities/frictionStudy/frictionStudy.py --quick on the given binaries and checks that it
# produced a complete study: study.csv with the expected 72 rows, every numeric column a
# finite number, study.md, and a valid PNG.
# Usage: frictionStudyQuick.sh BIN_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
bin=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
# A case name the study does not know: exit 2, naming the valid ones, before any run.
rc=0
err=$(/usr/bin/python3 "$src/utilities/frictionStudy/frictionStudy.py" --cases nope --bin "$bin" \
  --work "$work/bad" 2>&1) || rc=$?
[[ $rc == 2 && $err == *"'pennyCrack'"* && ! -e $work/bad/runs ]] ||
  { echo "FAIL: --cases nope: exit $rc: $err" >&2; exit 1; }
/usr/bin/python3 "$src/utilities/frictionStudy/frictionStudy.py" --quick --bin "$bin" \
  --work "$work" --out "$work/results" | tee "$work/log.frictionStudy"
out=$work/results
/usr/bin/python3 - "$out/study.csv" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
# quick plan: inclinedCrack 3 meshes x 2 orders x 2 optimizers x 2 tolerances = 24,
# paperBenchmark n=20: 2 orders x 4 optimizers x 2 tolerances = 16, n=40: 2 x 2 x 2 = 8,
# pennyCrack a/4 P1: 3 optimizers x 2 tolerances = 6, a/4 P2: 1 x 2 = 2, a/6 P1: 2 x 2 = 4,
# sneddonCrack a/16 and a/32: P1 2 optimizers x 2 tolerances, P2 1 x 2: 2 x 6 = 12
expected = 72
bad = []
if len(rows) != expected:
    bad.append("study.csv: %d rows, expected %d" % (len(rows), expected))
numeric = ["hOrN", "order", "tolerance", "iterations", "backSubstitutions", "factorSeconds",
           "wallSeconds", "relResidual", "maxExcessST", "slipError"]
for i, r in enumerate(rows, 2):
    for c in numeric:
        try:
            ok = math.isfinite(float(r[c]))
        except (KeyError, ValueError):
            ok = False
        if not ok:
            bad.append("study.csv line %d: %s = %r is not a finite number" % (i, c, r.get(c)))
    if not r.get("status") or r["status"].startswith(("crash", "timeout")):
        bad.append("study.csv line %d: status %r" % (i, r.get("status")))
for b in bad:
    print("FAIL:", b)
sys.exit(1 if bad else 0)
PY
grep -q '^## inclinedCrack' "$out/study.md" && grep -q '^## paperBenchmark' "$out/study.md" &&
  grep -q '^## pennyCrack' "$out/study.md" && grep -q '^## sneddonCrack' "$out/study.md" ||
  { echo "FAIL: study.md missing or without the case tables"; exit 1; }
[[ $(head -c 8 "$out/study.png" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] ||
  { echo "FAIL: study.png is not a PNG"; exit 1; }
grep -q 'semismoothNewton is .*× faster' "$work/log.frictionStudy" ||
  { echo "FAIL: the semismoothNewton/steepestDescent ratio was not printed"; exit 1; }
echo "frictionStudy --quick: 72 rows, study.md, study.png OK"
