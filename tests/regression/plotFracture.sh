#!/usr/bin/env bash
# Regression test for utilities/plotFracture/plotFracture.py on a solved copy of
# cases/paperBenchmark (made in WORK_DIR, never in cases/): the default run writes
# postProcessing/fracture_fracture.png and convergence.png, each a real PNG (magic bytes) and
# not empty; the user errors (no time folders, unknown fracture, unknown time, missing case)
# exit 1 with a message on stderr and write nothing.
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
echo "plotFracture: ok"
