#!/usr/bin/env bash
# The distributed engine (linearSolver mumps): the answer must not depend on the number of
# ranks. A case is run serially with cholmod (the reference), with mumps on one rank, and with
# 'mpirun -np 2' and '-np 3 frictionSolver -parallel' (oversubscribed on this 2-core machine);
# every fracture table of every time folder is compared (parallelCompare.py: each column to
# round-off of its own scale, states and statuses exactly), and each parallel run must have
# written the same files as the serial one, once (rank 0 writes). Also refused, with a
# message: -parallel with a one-rank solver, ranks started without -parallel, and
# splitFractureNodes under mpirun.
# Usage: parallelRanks.sh BIN_DIR SOURCE_DIR WORK_DIR CASE
#   CASE: paperBenchmarkP2 (2D, P2), fractureNetwork (2D: junctions, layers, fields, 8 steps),
#         strikeSlipFault (3D: gravity, in-situ stress, cohesion, 8 steps), faultInCubeP2 (3D,
#         P2: the consistent traction recovery), sneddonCrack (a crack that opens: contact
#         unilateral), refusals
set -u
bin=$1 src=$2 work=$3 scenario=$4
fail() { echo "FAIL [parallel.$scenario]: $*" >&2; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
command -v mpirun >/dev/null || fail "mpirun not found (openmpi-bin, etc/debian-packages)"
"$bin/frictionSolver" -listModels | grep -q "linear solvers.*mumps" ||
  fail "this build has no mumps linear solver (FRICTION_MUMPS)"

rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
setSolver() {  # setSolver CASE_DIR NAME
  sed -i "s/^linearSolver .*/linearSolver    $2;/" "$1/system/frictionSolution"
  grep -q "^linearSolver    $2;" "$1/system/frictionSolution" ||
    echo "linearSolver    $2;" >>"$1/system/frictionSolution"
}
prepare() {  # prepare NAME SOURCE_CASE: a split copy in NAME/case (VTK files are named after
  # the case folder: one name for every run); SOURCE_CASE is under the source tree's cases/,
  # or a path from the source tree
  local from=$src/cases/$2
  [[ -d $from ]] || from=$src/$2
  mkdir -p "$work/$1" && cp -r "$from" "$work/$1/case" || fail "cannot copy $2"
  # What a run of the case in the source tree left (./Allrun) goes: its Allclean knows what.
  if [[ -x $work/$1/case/Allclean ]]; then
    "$work/$1/case/Allclean" >/dev/null || fail "Allclean failed on the copy of $2"
  fi
  rm -rf "$work/$1/case"/log.* "$work/$1/case"/constant/splitMesh
  "$bin/splitFractureNodes" -case "$work/$1/case" >"$work/$1/case/log.splitFractureNodes" 2>&1 ||
    fail "splitFractureNodes failed on $2"
}

case $scenario in
  paperBenchmarkP2) base=paperBenchmark ;;
  faultInCubeP2) base=tests/regression/cases/faultInCube ;;
  fractureNetwork | strikeSlipFault | sneddonCrack) base=$scenario ;;
  refusals)
    prepare refuse paperBenchmark
    out=$(mpirun -np 2 "$bin/frictionSolver" -parallel -case "$work/refuse/case" 2>&1)
    rc=$?
    ((rc == 1)) || fail "-parallel with cholmod: exit $rc, expected 1: $out"
    grep -q "frictionSolution.*2 ranks.*linearSolver mumps" <<<"$out" ||
      fail "-parallel with cholmod: no message naming the file and the fix: $out"
    [[ -z $(ls -d "$work/refuse/case"/1 2>/dev/null) ]] || fail "-parallel with cholmod wrote a time folder"
    setSolver "$work/refuse/case" mumps
    out=$(mpirun -np 2 "$bin/frictionSolver" -case "$work/refuse/case" 2>&1)
    rc=$?
    ((rc != 0)) || fail "2 ranks without -parallel: exit 0: $out"
    grep -q "without -parallel" <<<"$out" || fail "2 ranks without -parallel: no message: $out"
    [[ -z $(ls -d "$work/refuse/case"/1 2>/dev/null) ]] || fail "ranks without -parallel wrote a time folder"
    out=$(mpirun -np 2 "$bin/splitFractureNodes" -case "$work/refuse/case" -overwrite 2>&1)
    rc=$?
    ((rc != 0)) || fail "splitFractureNodes on 2 ranks: exit 0: $out"
    grep -q "runs as one process" <<<"$out" || fail "splitFractureNodes on 2 ranks: no message: $out"
    echo "parallel.refusals: ok"
    exit 0
    ;;
  *) fail "unknown scenario $scenario" ;;
esac

runs=(serial mumps1 mumps2 mumps3)
for run in "${runs[@]}"; do
  prepare "$run" "$base"
  dir=$work/$run/case
  [[ $scenario == *P2 ]] && sed -i 's/^elementOrder .*/elementOrder    2;/' "$dir/system/frictionSolution"
  case $run in
    serial) setSolver "$dir" cholmod
      cmd=("$bin/frictionSolver" -case "$dir") ;;
    mumps1) setSolver "$dir" mumps
      cmd=("$bin/frictionSolver" -case "$dir") ;;
    mumps*) setSolver "$dir" mumps
      cmd=(mpirun -np "${run#mumps}" "$bin/frictionSolver" -parallel -case "$dir") ;;
  esac
  "${cmd[@]}" >"$dir/log.frictionSolver" 2>&1
  rc=$?
  ((rc == 0)) || { tail -20 "$dir/log.frictionSolver" >&2; fail "$run: exit $rc"; }
  log=$dir/log.frictionSolver
  case $run in
    mumps2 | mumps3)
      n=${run#mumps}
      grep -q "^frictionSolver ($n ranks)" "$log" || fail "$run: the log does not say $n ranks"
      grep -q "; $n ranks, .* GB on the largest rank" "$log" || fail "$run: no per-rank memory"
      grep -q "^Stiffness: each of the $n ranks assembled its own cells" "$log" ||
        fail "$run: the ranks did not assemble their own cells"
      # The log is written once: one End, one line per step.
      [[ $(grep -c "^End" "$log") == 1 ]] || fail "$run: the log has $(grep -c '^End' "$log") End lines"
      ;;
  esac
  grep -q "Interface operator: .* from the factorisation" "$log" ||
    fail "$run: the interface operator did not come from the factorisation"
done

# Every parallel run wrote what the serial run wrote: the same files (logs aside).
listing() { (cd "$work/$1/case" && find . -type f ! -name 'log.*' | LC_ALL=C sort); }
for run in mumps1 mumps2 mumps3; do
  diff <(listing serial) <(listing "$run") >/dev/null ||
    fail "$run wrote other files than the serial run: $(diff <(listing serial) <(listing "$run") | head -5)"
done
/usr/bin/python3 "$src/tests/regression/parallelCompare.py" "$work/serial/case" \
  "$work/mumps1/case" "$work/mumps2/case" "$work/mumps3/case" || fail "the tables differ (above)"
echo "parallel.$scenario: ok"
