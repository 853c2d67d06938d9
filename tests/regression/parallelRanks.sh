#!/usr/bin/env bash
# The distributed engine (linearSolver mumps): the answer must not depend on the number of
# ranks. A case is run serially with cholmod (the reference), with mumps on one rank, and with
# 'mpirun -np 2' and '-np 3 frictionSolver -parallel' (oversubscribed on this 2-core machine);
# every fracture table of every time folder is compared (parallelCompare.py: each column to
# round-off of its own scale, states and statuses exactly), and each parallel run must have
# written the same files as the serial one, once (rank 0 writes). Also refused, with a
# message: -parallel with a one-rank solver, ranks started without -parallel, and
# splitFractureNodes under mpirun. And errors on 2 and 3 ranks as serially: an output error
# ends every rank with exit 6 (outputErrors), a body that nothing holds is refused (rigidBody).
# Usage: parallelRanks.sh BIN_DIR SOURCE_DIR WORK_DIR CASE
#   CASE: paperBenchmarkP2 (2D, P2), fractureNetwork (2D: junctions, layers, fields, 8 steps),
#         strikeSlipFault (3D: gravity, in-situ stress, cohesion, 8 steps), faultInCubeP2 (3D,
#         P2: the consistent traction recovery), sneddonCrack (a crack that opens: contact
#         unilateral), faultNetworkBox (3D: fault surfaces crossing and abutting, the
#         intersection curves' sectors; 4 steps), faultNetworkBoxP2 (the same in P2: the
#         curves' mid-edge nodes too), pennyKrylov (the penny crack with Newton's krylov
#         variant: its back-substitutions and the probes' block of dual solves on the ranks),
#         refusals, outputErrors, rigidBody, outputErrorsAmg (outputErrors with linearSolver
#         amg; builds with FRICTION_HYPRE)
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
  faultNetworkBox | faultNetworkBoxP2) base=tests/regression/cases/faultNetworkBox ;;
  fractureNetwork | strikeSlipFault | sneddonCrack) base=$scenario ;;
  pennyKrylov) base=pennyCrack ;;
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
  outputErrors | outputErrorsAmg)
    # An output error on rank 0, the rank that writes, must end every rank at once with the
    # serial exit status 6 (before, rank 0 left the time loop and waited in MUMPS's clean-up,
    # the others in the next shared solve: both for ever). The class: postProcessing or VTK a
    # file, the case folder read-only, a disk that fills up in mid-run. Each on 2 ranks under a
    # timeout; every rank's own exit status is recorded (a wrapper around each), and what was
    # written must be whole.
    # outputErrorsAmg: the same with linearSolver amg, whose solves the ranks share through
    # hypre and a gather of each solution.
    prepare base paperBenchmark
    setSolver "$work/base/case" "$([[ $scenario == outputErrorsAmg ]] && echo amg || echo mumps)"
    mounted=()
    trap 'for m in "${mounted[@]}"; do umount "$m" 2>/dev/null; done' EXIT
    for sibling in postProcessingFile vtkFile readOnly diskFull; do
      c=$work/$sibling/case
      mkdir -p "$work/$sibling"
      expect=
      case $sibling in
        postProcessingFile)
          cp -r "$work/base/case" "$c" && echo x >"$c/postProcessing"
          expect="$c/postProcessing: cannot create the folder" ;;
        vtkFile)
          cp -r "$work/base/case" "$c" && echo x >"$c/VTK"
          expect="$c/VTK/fractures: cannot create the VTK output folder" ;;
        readOnly)
          cp -r "$work/base/case" "$c"
          # Root writes through permissions: a read-only bind mount stops it.
          if [[ $(id -u) -eq 0 ]]; then
            mount --bind "$c" "$c" && mounted+=("$c") && mount -o remount,bind,ro "$c" ||
              fail "readOnly: cannot mount the case read-only"
          else
            chmod -R a-w "$c"
          fi
          touch "$c/probe" 2>/dev/null && fail "readOnly: the case folder is still writable"
          # The case lock is the first file a run creates (before any output).
          expect="$c/.frictionSolver.lock: cannot create the lock file of the case" ;;
        diskFull)
          # Room for two or three written times (a .vtu is 750 kB) on a 3 MB tmpfs.
          if ! mount -t tmpfs -o size=3m tmpfs "$work/$sibling" 2>/dev/null; then
            echo "parallel.outputErrors: diskFull skipped: cannot mount a tmpfs (needs root)"
            continue
          fi
          mounted+=("$work/$sibling")
          cp -r "$work/base/case" "$c"
          sed -i 's/^deltaT .*/deltaT 0.025;/' "$c/system/controlDict"
          expect="No space left on device" ;;
      esac
      ranks=$work/$sibling.ranks
      rm -f "$ranks"
      start=$SECONDS
      timeout 60 mpirun -np 2 bash -c '"$0" "$@"; echo "rank $OMPI_COMM_WORLD_RANK exit $?" >>'"$ranks" \
        "$bin/frictionSolver" -parallel -case "$c" >"$work/$sibling.log" 2>&1
      rc=$?
      ((rc != 124)) || fail "$sibling: the 2 ranks still ran after 60 s: $(tail -5 "$work/$sibling.log")"
      [[ $(sort "$ranks" 2>/dev/null) == $'rank 0 exit 6\nrank 1 exit 6' ]] ||
        fail "$sibling: expected exit 6 on both ranks, got: $(cat "$ranks" 2>/dev/null) $(tail -5 "$work/$sibling.log")"
      grep -qF "$expect" "$work/$sibling.log" || fail "$sibling: no message '$expect': $(tail -5 "$work/$sibling.log")"
      (($(grep -c "frictionSolver: error" "$work/$sibling.log") == 1)) ||
        fail "$sibling: the error is not reported once: $(grep "error" "$work/$sibling.log")"
      # Whole outputs: each time folder complete, a VTK file and a .pvd entry per time folder,
      # no temporary leftovers.
      folders=$(cd "$c" && ls -d [0-9]* 2>/dev/null | grep -vx 0 | sort -g)
      for t in $folders; do
        [[ -f $c/$t/uniform/frictionState && -f $c/$t/D && -f $c/$t/fractures/fracture.dat ]] ||
          fail "$sibling: time folder $t is not whole"
      done
      if [[ $sibling == diskFull ]]; then
        [[ -n $folders ]] || fail "diskFull: no time folder fitted: nothing was tested"
        vtus=$(cd "$c/VTK" && ls case_*.vtu | sed 's/^case_//; s/\.vtu$//' | sort -g)
        [[ $vtus == "$folders" ]] || fail "diskFull: VTK files of times $(echo $vtus), time folders $(echo $folders)"
        pvd=$(sed -n 's/.*file="case_\(.*\)\.vtu".*/\1/p' "$c/VTK/case.pvd" | sort -g)
        [[ $pvd == "$folders" ]] || fail "diskFull: the .pvd lists $(echo $pvd), time folders $(echo $folders)"
      else
        [[ -z $folders ]] || fail "$sibling: time folders written: $folders"
      fi
      [[ -z $(cd "$c" && find . -name '.?*') ]] || fail "$sibling: leftovers: $(cd "$c" && find . -name '.?*')"
      echo "$sibling: exit 6 on both ranks after $((SECONDS - start)) s${folders:+, times $(echo $folders) whole}"
    done
    echo "parallel.outputErrors: ok"
    exit 0
    ;;
  rigidBody)
    # Every patch free, an initial stress the only load: the body can move as a rigid body,
    # and the run must say so (exit 4) whatever the number of ranks: serially with cholmod,
    # and with mumps on 1, 2 and 3 ranks, the same diagnosis, once, and nothing written. In 3D
    # (the penny crack: MUMPS on 2 and 3 ranks finds no null pivot there, and the run
    # 'converged') and in 2D (the paper benchmark).
    freeCase() {  # freeCase NAME SOURCE PATCHES STRESS
      prepare "$1" "$2"
      local c=$work/$1/case p
      {
        printf 'FoamFile\n{\n    version 2.0;\n    format ascii;\n    class pointVectorField;\n'
        printf '    object D;\n}\ndimensions [0 1 0 0 0 0 0];\nboundaryField\n{\n'
        for p in $3; do printf '    %s { type free; }\n' "$p"; done
        printf '}\n'
      } >"$c/0/D"
      printf 'FoamFile\n{\n    version 2.0;\n    format ascii;\n    class dictionary;\n    object effects;\n}\ninSitu { type initialStress; stress %s; }\n' \
        "$4" >"$c/constant/effects"
    }
    freeCase penny pennyCrack "outside" "(-1e7 -1e7 -2e7 0 0 0)"
    freeCase square paperBenchmark "bottom top left right" "(0 -1 0)"
    for name in penny square; do
      diagnosis=
      for run in cholmod mumps1 mumps2 mumps3; do
        c=$work/$name/$run
        cp -r "$work/$name/case" "$c"
        case $run in
          cholmod) setSolver "$c" cholmod; cmd=("$bin/frictionSolver" -case "$c") ;;
          mumps1) setSolver "$c" mumps; cmd=("$bin/frictionSolver" -case "$c") ;;
          *) setSolver "$c" mumps; cmd=(mpirun -np "${run#mumps}" "$bin/frictionSolver" -parallel -case "$c") ;;
        esac
        timeout 120 "${cmd[@]}" >"$c.log" 2>&1
        rc=$?
        ((rc == 4)) || fail "$name, $run: exit $rc, expected 4: $(grep -a "Factorisation\|error\|^End" "$c.log")"
        errors=$(grep -a "frictionSolver: error" "$c.log")
        # On failure, the run's whole output: a lost or doubled message must be diagnosable.
        (($(wc -l <<<"$errors") == 1)) ||
          fail "$name, $run: the error is not reported once: $errors; the output: $(tail -n 30 "$c.log")"
        grep -q "can move as a rigid body" <<<"$errors" ||
          fail "$name, $run: no rigid-body diagnosis: $errors; the output: $(tail -n 30 "$c.log")"
        # The same words on every rank count (the status names the backend's verdict).
        [[ -z $diagnosis || ${errors#*: error: } == "$diagnosis" ]] ||
          fail "$name, $run: another diagnosis than cholmod's: $errors"
        diagnosis=${errors#*: error: }
        [[ -z $(cd "$c" && ls -d [1-9]* 0.* 2>/dev/null) ]] || fail "$name, $run: a time folder was written"
      done
      echo "$name: exit 4 serially and on 1, 2 and 3 ranks: $diagnosis"
    done
    echo "parallel.rigidBody: ok"
    exit 0
    ;;
  *) fail "unknown scenario $scenario" ;;
esac

runs=(serial mumps1 mumps2 mumps3)
for run in "${runs[@]}"; do
  prepare "$run" "$base"
  dir=$work/$run/case
  [[ $scenario == *P2 ]] && sed -i 's/^elementOrder .*/elementOrder    2;/' "$dir/system/frictionSolution"
  if [[ $scenario == *Krylov ]]; then
    sed -i 's/^\( *type  *semismoothNewton;\)/\1 variant krylov;/' "$dir/system/frictionSolution"
    grep -q "variant krylov;" "$dir/system/frictionSolution" || fail "$run: variant krylov not set"
  fi
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
  if [[ $scenario == *Krylov ]]; then
    # No S: GMRES on products of back-substitutions, preconditioned by S probed by dual solves.
    grep -q "GMRES products per Newton iteration" "$log" || fail "$run: the step did not run GMRES"
  else
    grep -q "Interface operator: .* from the factorisation" "$log" ||
      fail "$run: the interface operator did not come from the factorisation"
  fi
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
