# Sourced by mumpsMemory.sh and amgSolver.sh: cases/pennyCrack's committed mesh split once in
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
