#!/usr/bin/env bash
# Regression test for utilities/plotFracture/plotFracture.py on a solved copy of
# cases/paperBenchmark (made in WORK_DIR, never in cases/): the default run writes
# postProcessing/fracture_fracture.png and convergence.png, each a real PNG (magic bytes) and
# not empty; tables with a fluid pressure (columns pressure, sigmaNEffective) get the panel of
# p and sigma'_n (the figure's height says how many panels), the others not; the user errors
# (no time folders, unknown fracture, unknown time, missing case) exit 1 with a message on
# stderr and write nothing; no axis of any figure drawn with an offset (tested on ST equal to
# mu_f up to round-off).
# Usage: plotFracture.sh SPLIT_BINARY SOLVER_BINARY SOURCE_DIR WORK_DIR
set -uo pipefail
split=$1 solver=$2 src=$3 work=$4
plot=$src/utilities/plotFracture/plotFracture.py
python=/usr/bin/python3  # Debian's, which sees python3-matplotlib (etc/debian-packages)
fail() { echo "FAIL [plotFracture]: $*"; exit 1; }

[[ -x $python ]] || fail "$python missing (install python3-matplotlib)"
"$python" -c "import matplotlib" 2>/dev/null || fail "matplotlib missing (install python3-matplotlib)"

rm -rf "$work" && mkdir -p "$work"
c=$work/paperBenchmark
cp -r "$src/cases/paperBenchmark" "$c"
# Keep only the inputs: whatever an earlier run left in cases/ must not be plotted.
"$c/Allclean" >/dev/null

isPng() {  # non-empty, starts with the 8-byte PNG signature
  [[ -s $1 ]] || return 1
  [[ $(head -c 8 "$1" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]]
}
pngHeight() {  # the height in pixels, from the IHDR chunk (bytes 20-23, big-endian)
  echo $((16#$(head -c 24 "$1" | tail -c 4 | od -An -tx1 | tr -d ' \n')))
}

# Errors before a solve: no time folders.
err=$("$python" "$plot" -case "$c" 2>&1 >/dev/null); rc=$?
((rc == 1)) || fail "no time folders: exit $rc, expected 1"
grep -qF "no time folders" <<<"$err" || fail "no time folders: stderr was: $err"
err=$("$python" "$plot" -case "$work/noSuchCase" 2>&1 >/dev/null); rc=$?
((rc == 1)) || fail "missing case: exit $rc, expected 1"
grep -qF "no such case folder" <<<"$err" || fail "missing case: stderr was: $err"

"$split" -case "$c" >"$c/log.splitFractureNodes" 2>&1 || fail "splitFractureNodes failed"
"$solver" -case "$c" >"$c/log.frictionSolver" 2>&1 || fail "frictionSolver failed: $(tail -5 "$c/log.frictionSolver")"

err=$("$python" "$plot" -case "$c" -fracture nope 2>&1 >/dev/null); rc=$?
((rc == 1)) || fail "unknown fracture: exit $rc, expected 1"
grep -qF "unknown fracture 'nope' (fractures: fracture)" <<<"$err" || fail "unknown fracture: stderr was: $err"
err=$("$python" "$plot" -case "$c" -times 0.123 2>&1 >/dev/null); rc=$?
((rc == 1)) || fail "unknown time: exit $rc, expected 1"
grep -qF "no time folder 0.123" <<<"$err" || fail "unknown time: stderr was: $err"
# The 3D profile options on a 2D table.
err=$("$python" "$plot" -case "$c" -line 0,0,0:1,0,0 2>&1 >/dev/null); rc=$?
((rc == 1)) || fail "-line on a 2D table: exit $rc, expected 1"
grep -qF "-line: fracture 'fracture' has a 2D table" <<<"$err" || fail "-line on 2D: stderr was: $err"
[[ ! -e $c/postProcessing/fracture_fracture.png ]] || fail "a failed run wrote a plot"

out=$("$python" "$plot" -case "$c" 2>&1); rc=$?
printf '%s\n' "$out"
((rc == 0)) || fail "plot run: exit $rc"
for png in "$c/postProcessing/fracture_fracture.png" "$c/postProcessing/convergence.png"; do
  isPng "$png" || fail "$png missing, empty or not a PNG"
done

# Explicit outputs and a chosen time.
out=$("$python" "$plot" -case "$c" -fracture fracture -times 1 -o "$work/f.png" \
      -convergence "$work/c.png" 2>&1); rc=$?
((rc == 0)) || fail "-o/-convergence run: exit $rc: $out"
isPng "$work/f.png" || fail "-o: $work/f.png missing or not a PNG"
isPng "$work/c.png" || fail "-convergence: $work/c.png missing or not a PNG"
# -help (OpenFOAM style) as well as -h: usage on stdout, exit 0.
for opt in -help -h; do
  out=$("$python" "$plot" $opt 2>&1); rc=$?
  ((rc == 0)) || fail "$opt: exit $rc: $out"
  grep -qF "usage: plotFracture" <<<"$out" || fail "$opt: no usage: $out"
done

# The ST axis and the mu_f line only where they mean something: a Coulomb law with
# compressed nodes. The paper benchmark is one; tension, Tresca and frictionless are not.
grep -qF "fracture_fracture.png (slip tendency and slip)" <<<"$(
  "$python" "$plot" -case "$c" -noConvergence 2>&1)" || fail "paperBenchmark: no ST panel"
variant() {  # name, then sed expressions on 0/D and constant/fractureProperties
  local v=$work/$1; shift
  rm -rf "$v" && cp -r "$src/cases/paperBenchmark" "$v" && "$v/Allclean" >/dev/null
  sed -i "$1" "$v/0/D"; sed -i "$2" "$v/constant/fractureProperties"
  "$split" -case "$v" >"$v/log.splitFractureNodes" 2>&1 || fail "$v: split failed"
  "$solver" -case "$v" >"$v/log.frictionSolver" 2>&1 || fail "$v: solver failed"
  "$python" "$plot" -case "$v" -noConvergence 2>&1
}
out=$(variant tension 's/(1 (-0.02 -0.025))/(1 (-0.02 0.025))/' 's/x/x/')
grep -qF "(tractions and slip)" <<<"$out" || fail "tension: ST panel drawn: $out"
out=$(variant tresca 's/x/x/' 's/law *coulomb;/law tresca; threshold 0.01;/; s/frictionCoefficient 0.2;//')
grep -qF "(tractions and slip)" <<<"$out" || fail "tresca: ST panel drawn: $out"
out=$(variant frictionless 's/x/x/' 's/law *coulomb;/law frictionless;/; s/frictionCoefficient 0.2;//')
grep -qF "(tractions and slip)" <<<"$out" || fail "frictionless: ST panel drawn: $out"

# Tips: state tip, the body's stress in the traction columns (no nan); plotted without an error.
ic=$work/inclinedCrack
cp -r "$src/cases/inclinedCrack" "$ic" && "$ic/Allclean" >/dev/null
"$split" -case "$ic" >"$ic/log.splitFractureNodes" 2>&1 || fail "inclinedCrack: split failed"
"$solver" -case "$ic" >"$ic/log.frictionSolver" 2>&1 || fail "inclinedCrack: solver failed"
grep -q " tip$" "$ic/1/fractures/crack.dat" || fail "inclinedCrack: no tip row"
! grep -qi "nan" "$ic/1/fractures/crack.dat" || fail "inclinedCrack: nan in the table"
out=$("$python" "$plot" -case "$ic" -noConvergence 2>&1) || fail "inclinedCrack: $out"
grep -qF "(slip tendency and slip)" <<<"$out" || fail "inclinedCrack: $out"
isPng "$ic/postProcessing/fracture_crack.png" || fail "inclinedCrack: no PNG"
# A crack that opens (contact unilateral) under a fluid pressure: the opening's panel and the
# pressure's (p and sigma'_n) too.
sn=$work/sneddonCrack
cp -r "$src/cases/sneddonCrack" "$sn" && "$sn/Allclean" >/dev/null
"$split" -case "$sn" >"$sn/log.splitFractureNodes" 2>&1 || fail "sneddonCrack: split failed"
"$solver" -case "$sn" >"$sn/log.frictionSolver" 2>&1 || fail "sneddonCrack: solver failed"
out=$("$python" "$plot" -case "$sn" -noConvergence 2>&1) || fail "sneddonCrack: $out"
grep -qF "fracture_crack.png (tractions, slip, opening, pressure and effective normal stress)" \
  <<<"$out" || fail "sneddonCrack: $out"
isPng "$sn/postProcessing/fracture_crack.png" || fail "sneddonCrack: no PNG"
((  $(pngHeight "$sn/postProcessing/fracture_crack.png") == 1500 )) ||
  fail "sneddonCrack: $(pngHeight "$sn/postProcessing/fracture_crack.png") px tall, expected 1500 (4 panels)"

# A fluid pressure (tables with 'pressure sigmaNEffective' before the state, as frictionSolver
# writes them with fracturePressure or faultPressure): the solved paperBenchmark's tables with
# the columns added, p uniform. A third panel (p and sigma'_n along s: the figure 10 in tall,
# 1200 px, against 7.5 in, 900 px, without it); ST while sigma'_n < 0 somewhere, the
# tractions once p exceeds every node's compression (sigma'_n >= 0): the test is on sigma'_n,
# not sigma_n.
withPressure() {  # name, p: a copy of the solved paperBenchmark with the pressure columns
  local v=$work/$1
  rm -rf "$v" && cp -r "$c" "$v" && rm -rf "$v/postProcessing"
  for f in "$v"/[1-9]*/fractures/*.dat; do
    "$python" - "$f" "$2" <<'PY' || fail "$1: cannot add the pressure columns"
import math, sys
path, p = sys.argv[1], float(sys.argv[2])
lines = open(path).read().splitlines()
names = lines[0][1:].split()
assert names[-1] == "state" and "pressure" not in names
out = ["# " + " ".join(names[:-1] + ["pressure", "sigmaNEffective", "state"])]
for line in lines[1:]:
    if line.startswith("#"):
        out.append(line)
        continue
    items = line.split()
    sn = float(items[names.index("sigmaN")])
    out.append(" ".join(items[:-1] + [repr(p), repr(sn + p) if math.isfinite(sn) else "nan",
                                      items[-1]]))
open(path, "w").write("\n".join(out) + "\n")
PY
  done
  echo "$v"
}
v=$(withPressure pressure 0.01)
out=$("$python" "$plot" -case "$v" -noConvergence 2>&1); rc=$?
((rc == 0)) || fail "pressure: exit $rc: $out"
grep -qF "fracture_fracture.png (slip tendency, slip, pressure and effective normal stress)" \
  <<<"$out" || fail "pressure: $out"
isPng "$v/postProcessing/fracture_fracture.png" || fail "pressure: no PNG"
(( $(pngHeight "$v/postProcessing/fracture_fracture.png") == 1200 )) ||
  fail "pressure: $(pngHeight "$v/postProcessing/fracture_fracture.png") px tall, expected 1200"
(( $(pngHeight "$c/postProcessing/fracture_fracture.png") == 900 )) ||
  fail "paperBenchmark: $(pngHeight "$c/postProcessing/fracture_fracture.png") px tall, expected 900"
v=$(withPressure pressureAboveConfinement 1)   # |sigma_n| < 0.1 on every node
out=$("$python" "$plot" -case "$v" -noConvergence 2>&1) || fail "pressure above: $out"
grep -qF "(tractions, slip, pressure and effective normal stress)" <<<"$out" ||
  fail "pressure above the confinement: the ST panel drawn: $out"
# No axis offsets: every node slipping, ST = mu_f to round-off (here 0.2 + k 1e-12): an axis
# offset would draw that noise as ticks of +-4e-12 above 0.2, a shape where there is none.
v=$work/roundOff
rm -rf "$v" && cp -r "$c" "$v" && rm -rf "$v/postProcessing"
for f in "$v"/[1-9]*/fractures/*.dat; do
  awk '/^#/ || $NF == "tip" { print; next }
       { $8 = sprintf("%.17g", 0.2 + (NR % 5) * 1e-12); print }' \
    "$f" >"$f.new" && mv "$f.new" "$f"
done
"$python" "$src/tests/regression/plotNoOffset.py" "$plot" -case "$v" ||
  fail "round-off ST: a figure drawn with an axis offset"
echo "plotFracture: ok"
