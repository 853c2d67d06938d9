#!/usr/bin/env bash
# linearSolver auto, the default (system/frictionSolution; README "Which linear solver"), on
# cases/pennyCrack's committed mesh (3D, 9 660 dofs, 273 fault nodes).
# Usage: linearSolverAuto.sh BIN_DIR SOURCE_DIR WORK_DIR SCENARIO
#   direct     the key left out: auto predicts CHOLMOD's factor (a few MB, far below the
#              memory available) and takes cholmod; the log says so with the prediction, and
#              the factorisation says it took the prediction's ordering (ordered once). Every
#              output is the one of 'linearSolver cholmod' byte for byte, but for the state's
#              one line that records the choice (what a restart takes again).
#   iterative  iterativeAbove 1e6 bytes, below the prediction: auto takes amg, the log says
#              why, and the fracture tables are cholmod's to 1e-9 of their scale (CG stops at a
#              relative residual of 1e-10: amgSolver.sh says why 1e-9 holds).
#   restart    a run that chose amg (a fault pressure rising in time, so that each step
#              solves), stopped after its first step and continued with
#              startFrom latestTime after the key that made it choose amg is gone: the
#              restart takes amg again (the state's record, said in the log), and every time
#              folder and history is that of the uninterrupted run byte for byte.
#   badValues  iterativeAbove with an explicit linearSolver, iterativeAbove 0, -1 or a word,
#              an unknown linearSolver: exit 1 naming the file, line and key, nothing written.
#   ranks      auto on 2 ranks takes mumps (the ranks share it; said in the log), and the
#              tables are the serial cholmod run's to 1e-9.
set -u
bin=$1 src=$2 work=$3 scenario=$4
fail() { echo "FAIL [linearSolverAuto.$scenario]: $*" >&2; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
compare=$src/tests/regression/parallelCompare.py

source "$src/tests/regression/pennyVariants.sh"
# auto NAME 'KEYS': a copy whose linearSolver line is gone (the default), KEYS in its place.
auto() {
  cp -r "$work/base" "$work/$1" || fail "cannot copy the case"
  sed -i "s|^linearSolver .*|$2|" "$work/$1/system/frictionSolution"
  [[ $2 == *linearSolver* ]] || ! grep -q "^linearSolver" "$work/$1/system/frictionSolution" ||
    fail "a linearSolver line is left"
}
run() {  # run NAME: frictionSolver on the copy NAME, log in NAME.log, exit 0 required
  "$bin/frictionSolver" -case "$work/$1" >"$work/$1.log" 2>&1 || fail "$1: exit $?: $(tail -n 5 "$work/$1.log")"
}
needAmg() {
  "$bin/frictionSolver" -listModels | grep -q "linear solvers.*amg" ||
    fail "this build has no amg linear solver (FRICTION_HYPRE)"
}
choice='^Linear solver auto: %s \(CHOLMOD'"'"'s factor, predicted by its METIS ordering and symbolic analysis in [0-9.e+-]+ s: [0-9.e+]+ entries, [0-9.e+-]+ GB, %s [0-9.e+-]+ GB%s\)$'

case $scenario in
  direct)
    variant() { pennyVariant "$@"; }
    variant cholmod cholmod ""
    run cholmod
    auto auto ""
    run auto
    log=$work/auto.log
    grep -q "^Elements: P1, linear solver auto, ordering auto, iterativeTolerance 1e-10$" "$log" ||
      fail "no settings line: $(grep -a "^Elements" "$log")"
    # shellcheck disable=SC2059
    grep -qE "$(printf "$choice" cholmod "<=" ", 80 % of the memory available; the factorisation takes this ordering")" "$log" ||
      fail "no choice line: $(grep -a "^Linear solver" "$log")"
    grep -q "^Setup: ordering and analysis (METIS, auto, 3D, [0-9]* unknowns, ordered once for the prediction;" "$log" ||
      fail "the factorisation ordered again: $(grep -a "^Setup: ordering" "$log")"
    # The same outputs: every file the cholmod run wrote, byte for byte, but the state's record.
    files=$(cd "$work/cholmod" && find 1 postProcessing -type f | sort)
    [[ -n $files ]] || fail "the cholmod run wrote nothing"
    n=0
    for f in $files; do
      if [[ $f == 1/uniform/frictionState ]]; then
        diff <(grep -v "^linearSolver" "$work/auto/$f") "$work/cholmod/$f" >/dev/null ||
          fail "$f differs beyond the linearSolver record"
        grep -q "^linearSolver *cholmod;$" "$work/auto/$f" || fail "$f: no record of the choice"
      else
        cmp -s "$work/cholmod/$f" "$work/auto/$f" || fail "$f differs from the cholmod run's"
      fi
      n=$((n + 1))
    done
    [[ $(cd "$work/auto" && find 1 postProcessing -type f | sort) == "$files" ]] ||
      fail "the runs wrote different files"
    echo "$n files as the cholmod run's"
    ;;
  iterative)
    needAmg
    variant() { pennyVariant "$@"; }
    variant cholmod cholmod ""
    run cholmod
    auto auto "iterativeAbove 1e6;"
    run auto
    log=$work/auto.log
    # shellcheck disable=SC2059
    grep -qE "$(printf "$choice" amg ">" " \(iterativeAbove\)")" "$log" ||
      fail "no choice line: $(grep -a "^Linear solver" "$log")"
    grep -q "; every solve reached its tolerance$" "$log" || fail "no amg summary line"
    grep -q "^linearSolver *amg;$" "$work/auto/1/uniform/frictionState" || fail "no record of the choice"
    python3 "$compare" "$work/cholmod" "$work/auto" || fail "amg by auto: tables differ from cholmod's"
    ;;
  restart)
    needAmg
    # A fluid pressure on the fault that rises: the second step's loads are not the first's.
    for name in whole part; do
      auto $name "iterativeAbove 1e6;"
      sed -i 's/^endTime .*/endTime 2;/' "$work/$name/system/controlDict"
      echo 'fluid { type fracturePressure; fracture fault; pressure table ((0 0) (2 2e6)); }' \
        >>"$work/$name/constant/effects"
    done
    run whole
    grep -q "^Linear solver auto: amg (" "$work/whole.log" || fail "whole: amg not chosen"
    sed -i 's/^endTime .*/endTime 1;/' "$work/part/system/controlDict"
    run part
    [[ -d $work/part/1 && ! -d $work/part/2 ]] || fail "part: not stopped after time 1"
    # Continued without the key that made auto take amg: a fresh choice would be cholmod.
    sed -i 's/^endTime .*/endTime 2;/; s/^startFrom .*/startFrom latestTime;/' "$work/part/system/controlDict"
    sed -i 's/^iterativeAbove .*//' "$work/part/system/frictionSolution"
    "$bin/frictionSolver" -case "$work/part" >"$work/part2.log" 2>&1 || fail "restart: exit $?: $(tail -n 5 "$work/part2.log")"
    grep -q "^Linear solver auto: amg (as the run this one continues: its newest time folder's state)$" \
      "$work/part2.log" || fail "restart: no record taken: $(grep -a "^Linear solver" "$work/part2.log")"
    files=$(cd "$work/whole" && find 1 2 postProcessing -type f | sort)
    [[ -n $files ]] || fail "the whole run wrote nothing"
    [[ $(cd "$work/part" && find 1 2 postProcessing -type f | sort) == "$files" ]] ||
      fail "the runs wrote different files"
    for f in $files; do
      cmp -s "$work/whole/$f" "$work/part/$f" || fail "$f differs from the uninterrupted run's"
    done
    echo "$(wc -w <<<"$files") files as the uninterrupted run's"
    ;;
  badValues)
    n=0
    # bad NAME 'LINE' EXPECTED...: exit 1, file:line and the texts, the case unchanged
    bad() {
      local name=$1 keys=$2
      shift 2
      auto "$name" "$keys"
      pennyRefused "$name" "^${keys%% *}" "$@"
    }
    bad explicit "iterativeAbove 1e9; linearSolver cholmod;" "key 'iterativeAbove'" "needs 'linearSolver auto;'"
    bad zero "iterativeAbove 0;" "iterativeAbove"
    bad negative "iterativeAbove -1;" "iterativeAbove"
    bad word "iterativeAbove large;" "iterativeAbove"
    bad unknown "linearSolver automatic;" "linearSolver" "auto"
    echo "$n refusals"
    ;;
  ranks)
    command -v mpirun >/dev/null || fail "mpirun not found (openmpi-bin, etc/debian-packages)"
    variant() { pennyVariant "$@"; }
    variant cholmod cholmod ""
    run cholmod
    auto auto2 ""
    timeout -s KILL 280 mpirun -np 2 "$bin/frictionSolver" -parallel -case "$work/auto2" \
      >"$work/auto2.log" 2>&1 || fail "auto on 2 ranks: exit $?: $(tail -n 5 "$work/auto2.log")"
    grep -q "^Linear solver auto: mumps (2 ranks share it)$" "$work/auto2.log" ||
      fail "no choice line: $(grep -a "^Linear solver" "$work/auto2.log")"
    python3 "$compare" "$work/cholmod" "$work/auto2" || fail "auto on 2 ranks: tables differ"
    ;;
  *) fail "unknown scenario" ;;
esac
echo "linearSolverAuto.$scenario: ok"
