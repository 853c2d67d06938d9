#!/usr/bin/env bash
# The iterative volume solver (system/frictionSolution: linearSolver amg, iterativeTolerance;
# README "The largest 3D models") on cases/pennyCrack's committed mesh (3D, 273 fault nodes).
# Usage: amgSolver.sh BIN_DIR SOURCE_DIR WORK_DIR SCENARIO
#   penny      linearSolver amg against linearSolver cholmod, both with Newton's variant krylov
#              (amg's variant auto takes it: the log says why), every column of the fracture
#              table to 1e-9 of its scale (parallelCompare.py). Why 1e-9 holds: CG stops at a
#              relative residual of 1e-10, and the log's check solve measures the forward error
#              it leaves (1.6e-9 in the displacement); the tractions and slips are averages over
#              the fault's cells and Newton's own stop is 1e-10 (measured: 3.4e-12 of the
#              column's scale). The log states the hierarchy, the check solve and, at the end,
#              the solves, their iterations and that each reached its tolerance.
#   unreachable  iterativeTolerance 1e-30, below what double precision can reach: the check
#              solve stops at the iteration limit, exit 4 with the reason, no time folder.
#   floating   every patch of the case free (a body nothing holds): exit 4, the rigid motion
#              named, no time folder; CG ends at its iteration limit, not in a hang.
#   nearlyIncompressible  ν = 0.49 (label stability), Newton's variant condensed (S from 666
#              CG solves: krylov's probed preconditioner needs thousands of GMRES products at
#              this ν, each a CG solve here): the solves take 2-3× the iterations of ν = 0.25,
#              and the status is the truth: either converged with the tables within 1e-6 of
#              cholmod's (κ grows with λ/μ = 24), or inaccurate, the step's note naming amg's
#              iterativeTolerance as the bound (measured: inaccurate, |D|/|Σ| 2.7e-10 written
#              against 1e-10); exit 0 or 3 accordingly, within the timeout.
#   badValues  iterativeTolerance with linearSolver cholmod, iterativeTolerance 0, 0.5 or a
#              word: exit 1 naming the file, line and key, nothing written.
#   ranks      amg on 2 and 3 ranks (mpirun -parallel): cholmod's serial tables to 1e-9; a
#              body nothing holds: exit 4 on every rank, one diagnosis.
set -u
bin=$1 src=$2 work=$3 scenario=$4
fail() { echo "FAIL [amgSolver.$scenario]: $*" >&2; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
"$bin/frictionSolver" -listModels | grep -q "linear solvers.*amg" ||
  fail "this build has no amg linear solver (FRICTION_HYPRE)"
compare=$src/tests/regression/parallelCompare.py

source "$src/tests/regression/pennyVariants.sh"
variant() { pennyVariant "$@"; }  # variant NAME SOLVER 'KEYS'

case $scenario in
  penny)
    variant direct cholmod ""
    sed -i 's/^\( *type *semismoothNewton;\)/\1 variant krylov;/' "$work/direct/system/frictionSolution"
    grep -q "variant krylov;" "$work/direct/system/frictionSolution" || fail "no variant line"
    "$bin/frictionSolver" -case "$work/direct" >"$work/direct.log" 2>&1 ||
      fail "direct: exit $?: $(tail -n 5 "$work/direct.log")"
    variant amg amg ""
    "$bin/frictionSolver" -case "$work/amg" >"$work/amg.log" 2>&1 ||
      fail "amg: exit $?: $(tail -n 5 "$work/amg.log")"
    log=$work/amg.log
    grep -q "^Elements: P1, linear solver amg, iterativeTolerance 1e-10$" "$log" ||
      fail "no settings line: $(grep -a "^Elements" "$log")"
    grep -qE "^Linear solver amg: BoomerAMG \(3 displacement components, [0-9.e+]+ nonzeros\) set up in [0-9.e+-]+ s; CG to a relative residual of 1e-10: the check solve A x = A r took [0-9]+ iterations \([0-9.e+-]+ s\), forward error \|x - r\|/\|r\| [0-9.e+-]+$" \
      "$log" || fail "no setup line: $(grep -a "^Linear solver" "$log")"
    forward=$(sed -n 's/^Linear solver amg: BoomerAMG.*forward error |x - r|\/|r| \([0-9.e+-]*\)$/\1/p' "$log")
    awk -v f="$forward" 'BEGIN { exit !(f > 0 && f < 1e-6) }' || fail "check solve's forward error $forward"
    grep -q "^Newton variant: krylov (variant auto: .*; krylov all the same: linear solver amg has no factor, so S would cost one solve per jump unknown)$" \
      "$log" || fail "no variant line: $(grep -a "^Newton variant" "$log")"
    grep -qE "^Linear solver amg: [1-9][0-9]* solves \(the check included\), [1-9][0-9]* CG iterations \([0-9]+ per solve\), the largest relative residual at a stop [0-9.e+-]+; every solve reached its tolerance$" \
      "$log" || fail "no summary line: $(grep -a "^Linear solver amg: [0-9]" "$log")"
    python3 "$compare" "$work/direct" "$work/amg" || fail "amg: tables differ from cholmod's"
    ;;
  unreachable | floating)
    if [[ $scenario == unreachable ]]; then
      variant run amg "iterativeTolerance 1e-30;"
      expect="CG did not reach its tolerance 1e-30"
    else
      variant run amg ""
      # The patch free, an initial stress the only load: nothing holds the body.
      printf 'FoamFile\n{\n    version 2.0;\n    format ascii;\n    class pointVectorField;\n    object D;\n}\ndimensions [0 1 0 0 0 0 0];\nboundaryField\n{\n    outside { type free; }\n}\n' \
        >"$work/run/0/D"
      printf 'FoamFile\n{\n    version 2.0;\n    format ascii;\n    class dictionary;\n    object effects;\n}\ninSitu { type initialStress; stress (-1e7 -1e7 -2e7 0 0 0); }\n' \
        >"$work/run/constant/effects"
      expect="can move as a rigid body"
    fi
    before=$(listing run)
    start=$SECONDS
    out=$(timeout -s KILL 300 "$bin/frictionSolver" -case "$work/run" 2>&1)
    rc=$?
    ((rc == 4)) || fail "exit $rc, expected 4: $(tail -n 8 <<<"$out")"
    grep -qF "$expect" <<<"$out$(cat "$work/run/log.frictionSolver" 2>/dev/null)" ||
      fail "no '$expect' in: $(tail -n 8 <<<"$out")"
    [[ -z $(comm -13 <(echo "$before") <(listing run) | grep '^\./[0-9]') ]] ||
      fail "a time folder was written"
    echo "exit 4 after $((SECONDS - start)) s: $(grep -F "$expect" <<<"$out" | head -n 1)"
    ;;
  nearlyIncompressible)
    for solver in cholmod amg; do
      variant "$solver" "$solver" ""
      sed -i 's/^nu .*/nu 0.49;/' "$work/$solver/constant/mechanicalProperties"
      sed -i 's/^\( *type *semismoothNewton;\)/\1 variant condensed;/' "$work/$solver/system/frictionSolution"
      grep -q "variant condensed;" "$work/$solver/system/frictionSolution" || fail "no variant line"
      timeout -s KILL 280 "$bin/frictionSolver" -case "$work/$solver" >"$work/$solver.log" 2>&1
      rc=$?
      [[ $solver == amg ]] || ((rc == 0)) || fail "cholmod: exit $rc: $(tail -n 5 "$work/$solver.log")"
    done
    step=$(grep -a "^Time = 1 " "$work/amg.log")
    [[ -n $step ]] || fail "amg: no step line (exit $rc): $(tail -n 5 "$work/amg.log")"
    if ((rc == 0)); then
      grep -q "  converged  " <<<"$step" || fail "amg: exit 0 but the step is not converged: $step"
      python3 "$compare" --tolerance 1e-6 "$work/cholmod" "$work/amg" || fail "amg: tables differ from cholmod's"
      echo "converged: $step"
    elif ((rc == 3)); then
      grep -q "  inaccurate  " <<<"$step" || fail "amg: exit 3 but the step is not inaccurate: $step"
      grep -qF "linear solver amg solves only to iterativeTolerance 1e-10" <<<"$step" ||
        fail "amg: the note does not name the solver's tolerance: $step"
      grep -q "^# status inaccurate " "$work/amg/1/fractures/fault.dat" ||
        fail "amg: the table's status is not inaccurate: $(grep -a "^# status" "$work/amg/1/fractures/fault.dat")"
      echo "inaccurate, said: ${step:0:160}"
    else
      fail "amg: exit $rc: $(tail -n 5 "$work/amg.log")"
    fi
    ;;
  badValues)
    n=0
    # bad NAME SOLVER 'KEYS' EXPECTED...: exit 1, file:line and the texts, the case unchanged
    bad() {
      local name=$1 solver=$2 keys=$3
      shift 3
      variant "$name" "$solver" "$keys"
      pennyRefused "$name" "^linearSolver" "$@"
    }
    bad direct cholmod "iterativeTolerance 1e-8;" "key 'iterativeTolerance'" "needs 'linearSolver amg'"
    bad zero amg "iterativeTolerance 0;" "iterativeTolerance"
    bad large amg "iterativeTolerance 0.5;" "iterativeTolerance"
    bad word amg "iterativeTolerance tight;" "iterativeTolerance"
    echo "$n refusals"
    ;;
  ranks)
    # On 2 and 3 ranks (each assembles its own cells, hypre adds them and shares the rows):
    # the serial cholmod run's tables to 1e-9 (as the serial amg run's, above), and a body
    # nothing holds ends every rank with exit 4 and one diagnosis.
    command -v mpirun >/dev/null || fail "mpirun not found (openmpi-bin, etc/debian-packages)"
    variant direct cholmod ""
    sed -i 's/^\( *type *semismoothNewton;\)/\1 variant krylov;/' "$work/direct/system/frictionSolution"
    "$bin/frictionSolver" -case "$work/direct" >"$work/direct.log" 2>&1 ||
      fail "direct: exit $?: $(tail -n 5 "$work/direct.log")"
    for np in 2 3; do
      variant amg$np amg ""
      timeout -s KILL 280 mpirun -np $np "$bin/frictionSolver" -parallel -case "$work/amg$np" \
        >"$work/amg$np.log" 2>&1 || fail "amg on $np ranks: exit $?: $(tail -n 5 "$work/amg$np.log")"
      grep -q "^Stiffness: each of the $np ranks assembled its own cells" "$work/amg$np.log" ||
        fail "amg on $np ranks: the ranks did not assemble their own cells"
      grep -q "; every solve reached its tolerance$" "$work/amg$np.log" || fail "amg on $np ranks: no summary"
      python3 "$compare" "$work/direct" "$work/amg$np" || fail "amg on $np ranks: tables differ"
    done
    variant floating amg ""
    printf 'FoamFile\n{\n    version 2.0;\n    format ascii;\n    class pointVectorField;\n    object D;\n}\ndimensions [0 1 0 0 0 0 0];\nboundaryField\n{\n    outside { type free; }\n}\n' \
      >"$work/floating/0/D"
    printf 'FoamFile\n{\n    version 2.0;\n    format ascii;\n    class dictionary;\n    object effects;\n}\ninSitu { type initialStress; stress (-1e7 -1e7 -2e7 0 0 0); }\n' \
      >"$work/floating/constant/effects"
    out=$(timeout -s KILL 280 mpirun -np 2 "$bin/frictionSolver" -parallel -case "$work/floating" 2>&1)
    rc=$?
    ((rc == 4)) || fail "floating on 2 ranks: exit $rc, expected 4: $(tail -n 8 <<<"$out")"
    (($(grep -c "frictionSolver: error" <<<"$out") == 1)) || fail "floating: the error is not reported once: $out"
    grep -q "can move as a rigid body" <<<"$out" || fail "floating: no rigid-body diagnosis: $out"
    ;;
  *) fail "unknown scenario" ;;
esac
echo "amgSolver.$scenario: ok"
