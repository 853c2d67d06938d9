# Sourced by mumpsMemory.sh, amgSolver.sh and linearSolverAuto.sh: cases/pennyCrack's committed mesh split once in
# $work/base (VTK off), copies of it with another linearSolver line, and a listing of a copy's
# files. Needs bin, src, work and fail() set by the caller.
rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
cp -r "$src/cases/pennyCrack" "$work/base" || fail "cannot copy cases/pennyCrack"
rm -rf "$work/base"/log.* "$work/base/constant/splitMesh"
sed -i 's/^writeVTK.*//; $a writeVTK no;' "$work/base/system/controlDict"
"$bin/splitFractureNodes" -case "$work/base" >"$work/base/log.splitFractureNodes" 2>&1 ||
  fail "splitFractureNodes failed"
# pennyVariant NAME SOLVER 'KEYS': a copy of the case whose linearSolver line is
# 'linearSolver SOLVER; KEYS'.
pennyVariant() {
  cp -r "$work/base" "$work/$1" || fail "cannot copy the case"
  sed -i "s|^linearSolver .*|linearSolver    $2; $3|" "$work/$1/system/frictionSolution"
  grep -q "^linearSolver    $2;" "$work/$1/system/frictionSolution" || fail "no linearSolver line"
}
# Files of the case folder NAME other than its logs (what a run must not leave behind).
listing() { (cd "$work/$1" && find . ! -name 'log.*' | sort); }
# pennyRefused NAME 'LINE' TEXT...: frictionSolver on the copy NAME must refuse it with exit 1,
# name system/frictionSolution and the number of the first line starting with LINE (a regular
# expression), print every TEXT, and leave the case's files as they were. Counts in n.
pennyRefused() {
  local name=$1 start=$2
  shift 2
  local before line out rc
  before=$(listing "$name")
  line=$(grep -n "$start" "$work/$name/system/frictionSolution" | head -1 | cut -d: -f1)
  [[ -n $line ]] || fail "$name: no line starting with $start"
  out=$("$bin/frictionSolver" -case "$work/$name" 2>&1)
  rc=$?
  ((rc == 1)) || fail "$name: exit $rc, expected 1: $out"
  grep -qF "system/frictionSolution:$line" <<<"$out" || fail "$name: no file:line ($line): $out"
  for e in "$@"; do grep -qF -- "$e" <<<"$out" || fail "$name: no '$e' in: $out"; done
  [[ $(listing "$name") == "$before" ]] ||
    fail "$name: the case changed: $(comm -3 <(echo "$before") <(listing "$name"))"
  n=$((n + 1))
}
