#!/usr/bin/env bash
# No data loss. A run killed (SIGKILL at chosen instants of writing, or at random) or stopped
# (SIGTERM, SIGINT) and restarted with startFrom latestTime leaves every output file — time
# folders, VTK/*.vtu, VTK/fractures/*.vtp, VTK/<case>.pvd, postProcessing/convergence.dat —
# byte for byte as an uninterrupted run does, and no temporary file or folder. A full disk
# (time folders, or convergence.dat) stops the run with exit 6 and a message naming the file,
# and leaves what was written whole. A second run over existing time folders is refused;
# -overwrite removes the earlier run's outputs and nothing else. A restart with another
# deltaT or a later endTime continues from the saved time. The log reaches its file line by
# line (logFlushed).
# Usage: noDataLoss.sh BIN_DIR SOURCE_DIR WORK_DIR SCENARIO [KILL_AT_RENAME_LIBRARY]
set -uo pipefail
bin=$1 src=$2 work=$3 scenario=$4 killLib=${5:-}
# A sanitized solver (FRICTION_SANITIZE) needs the ASan runtime first among the preloaded
# libraries, before the rename() hook.
asanLib=$(ldd "$bin/frictionSolver" 2>/dev/null | awk '/libasan/ {print $3}')
preload="${asanLib:+$asanLib }$killLib"
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL [$scenario]: $*"; exit 1; }

# The paper benchmark ramped over STEPS steps, written every 5 steps, in <dir>/case (the
# folder's name is the VTK files' base name, so every copy must have the same one).
makeCase() {  # makeCase DIR STEPS
  # Clean a copy outside the target first: what an earlier ./Allrun left in cases/ must not
  # come along (nor fill the small tmpfs of diskFull before it is cleaned).
  local stage="$work/stage.$RANDOM"
  cp -r "$src/cases/paperBenchmark" "$stage"
  "$stage/Allclean" >/dev/null
  mkdir -p "$1"
  mv "$stage" "$1/case"
  setKey "$1/case" deltaT "$(awk -v n="$2" 'BEGIN{printf "%.10g", 1/n}')"
  setKey "$1/case" writeInterval 5
  # The case's own optimizer, condensed Newton: it builds S before the first step of every
  # run, a restart included; the time folders must not show it.
  "$bin/splitFractureNodes" -case "$1/case" >"$1/case/log.splitFractureNodes" 2>&1 || fail "split failed"
  if ((${#launcher[@]})); then
    sed -i 's/^linearSolver .*/linearSolver mumps;/' "$1/case/system/frictionSolution"
    grep -q "^linearSolver mumps;" "$1/case/system/frictionSolution" || fail "cannot set mumps"
  fi
}
setKey() {  # setKey CASE KEY VALUE: set a controlDict key
  sed -i "s/^$2 .*/$2 $3;/" "$1/system/controlDict"
  grep -q "^$2 $3;" "$1/system/controlDict" || fail "cannot set $2 in $1/system/controlDict"
}
# The parallel scenarios run every solve on 2 ranks with linearSolver mumps.
launcher=()
if [[ $scenario == parallel* ]]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
  launcher=(mpirun -np 2)
fi
solve() {  # solve CASE LOG [ARGS...]: the exit code in $rc
  local c=$1 log=$2
  shift 2
  if ((${#launcher[@]})); then
    "${launcher[@]}" "$bin/frictionSolver" -parallel -case "$c" "$@" >"$log" 2>&1
  else
    "$bin/frictionSolver" -case "$c" "$@" >"$log" 2>&1
  fi
  rc=$?
  return $rc  # also for a solve in the background: wait gives it
}
timeFolders() { (cd "$1" && ls -d [0-9]* 2>/dev/null | grep -vx 0 | sort -g); }
# Everything a run writes: all files but the logs and the inputs.
outputs() { (cd "$1" && find . -type f ! -name 'log.*' ! -path './system/*' ! -path './constant/*' ! -path './0/*' | sort); }

# sameOutputs REFERENCE CASE [EXTRA_TIME]: every output file of CASE is byte for byte the
# reference's, none is missing or extra, and no hidden leftover exists. EXTRA_TIME: a time
# CASE wrote and the reference did not (a stop by signal writes the current step): its
# folder, VTK files and .pvd entry are allowed on top.
sameOutputs() {
  local ref=$1 c=$2 extra=${3:-} f
  local mine
  mine=$(outputs "$c")
  if [[ -n $extra ]]; then
    mine=$(grep -v -e "^\./$extra/" -e "_$extra\.vt[up]\$" <<<"$mine")
  fi
  [[ $(outputs "$ref" | wc -l) -gt 5 ]] || fail "the reference wrote too few files: nothing is compared"
  diff <(outputs "$ref") <(echo "$mine") >"$work/files.diff" ||
    fail "files differ from the uninterrupted run (< reference, > restarted): $(head -20 "$work/files.diff")"
  for f in $(outputs "$ref"); do
    if [[ -n $extra && $f == *.pvd ]]; then
      cmp -s "$ref/$f" <(grep -v "_$extra\.vt[up]\"" "$c/$f") || fail "$f differs (besides the entry of $extra)"
    else
      cmp -s "$ref/$f" "$c/$f" || fail "$f differs from the uninterrupted run"
    fi
  done
  [[ -z $(cd "$c" && find . -name '.?*') ]] || fail "leftovers: $(cd "$c" && find . -name '.?*')"
}

# snapshot [CASE]: every folder, and every file with its size, modification time and checksum
# (the logs aside): equal before and after a run that must change nothing, rewrites included.
# datedBack [CASE]: the files dated back to 2001 first, so that a rewrite shows in its time.
snapshot() {
  (cd "${1:-$c}" && find . ! -name 'log.*' \( -type d -printf '%p/\n' -o -printf '%p %s %T@\n' \) | sort &&
    find . -type f ! -name 'log.*' -exec md5sum {} + | sort)
}
datedBack() { find "${1:-$c}" -type f ! -name 'log.*' -exec touch -d @1000000000 {} +; }

# reference STEPS [WRITE_INTERVAL]: an uninterrupted run in $work/reference/case
reference() {
  makeCase "$work/reference" "$1"
  [[ -z ${2:-} ]] || setKey "$work/reference/case" writeInterval "$2"
  solve "$work/reference/case" "$work/reference/case/log.frictionSolver"
  ((rc == 0)) || fail "reference run failed: $(tail -3 "$work/reference/case/log.frictionSolver")"
}

# sameOutputsParallel REFERENCE CASE [EXTRA_TIME]: as sameOutputs, for runs on several ranks,
# which are reproducible to round-off only (MUMPS adds the contributions of other ranks in the
# order they arrive: two uninterrupted 2-rank runs of this case differ by 1e-14 of the tractions).
# The same files, no leftovers, the same .pvd and the same (time, iteration) history, byte for
# byte; the fracture tables equal to round-off (parallelCompare.py).
sameOutputsParallel() {
  local ref=$1 c=$2 extra=${3:-} mine
  mine=$(outputs "$c")
  [[ -n $extra ]] && mine=$(grep -v -e "^\./$extra/" -e "_$extra\.vt[up]\$" <<<"$mine")
  [[ $(outputs "$ref" | wc -l) -gt 5 ]] || fail "the reference wrote too few files: nothing is compared"
  diff <(outputs "$ref") <(echo "$mine") >"$work/files.diff" ||
    fail "files differ from the uninterrupted run (< reference, > restarted): $(head -20 "$work/files.diff")"
  [[ -z $(cd "$c" && find . -name '.?*') ]] || fail "leftovers: $(cd "$c" && find . -name '.?*')"
  local pvd=VTK/case.pvd
  cmp -s "$ref/$pvd" <(grep -v "_${extra:-none}\.vt[up]\"" "$c/$pvd") || fail "$pvd differs"
  cmp -s <(awk '{print $1, $2}' "$ref/postProcessing/convergence.dat") \
    <(awk '{print $1, $2}' "$c/postProcessing/convergence.dat") ||
    fail "the (time, iteration) history differs from the uninterrupted run"
  /usr/bin/python3 "$src/tests/regression/parallelCompare.py" "$ref" "$c" ||
    fail "the fracture tables differ from the uninterrupted run beyond round-off"
}

# restartAndCompare CASE [EXTRA_TIME]
restartAndCompare() {
  local c=$1
  setKey "$c" startFrom latestTime
  solve "$c" "$c/log.2"
  ((rc == 0)) || fail "restart failed (exit $rc): $(tail -3 "$c/log.2")"
  if ((${#launcher[@]})); then
    sameOutputsParallel "$work/reference/case" "$c" "${2:-}"
  else
    sameOutputs "$work/reference/case" "$c" "${2:-}"
  fi
}

case $scenario in
killRestart)
  steps=40
  reference $steps
  [[ -f $killLib ]] || fail "no kill library given"
  # Instants (the N-th rename whose "old -> new" contains the text): inside the time folder
  # being written, a .vtu and a .vtp written but not renamed (temporary files left), all VTK
  # files but the .pvd, all but the time folder's own rename (the commit).
  n=0
  for point in "frictionState|4" ".vtu|4" ".vtp|4" ".pvd|4" ".partial -> |4"; do
    label=kill$((++n))  # (a folder name must not contain the text looked for)
    makeCase "$work/$label" $steps
    c=$work/$label/case
    FRICTION_KILL_AT_RENAME=$point LD_PRELOAD=$preload "$bin/frictionSolver" -case "$c" >"$c/log.1" 2>&1
    rc=$?
    ((rc == 137)) || fail "[$point] not killed (exit $rc): nothing was tested"
    [[ -n $(cd "$c" && find . -name '.?*') ]] || fail "[$point] the kill left nothing half-written: nothing was tested"
    last=$(timeFolders "$c" | tail -1)
    echo "[$point] killed after time $last; restarting"
    restartAndCompare "$c"
    grep -q "Restarting from time $last " "$c/log.2" || fail "[$point] did not restart from $last"
  done
  # And at a random instant, as soon as a few time folders exist. On a loaded machine the
  # run may end between two looks at its folders (the whole run takes about a second): then
  # it is tried again on a fresh copy, up to five times.
  for attempt in 1 2 3 4 5; do
    makeCase "$work/random$attempt" $steps
    c=$work/random$attempt/case
    "$bin/frictionSolver" -case "$c" >"$c/log.1" 2>&1 &
    pid=$!
    for _ in $(seq 2000); do (($(timeFolders "$c" | wc -l) >= 3)) && break; sleep 0.002; done
    kill -KILL $pid
    wait $pid 2>/dev/null
    rc=$?
    ((rc == 137)) && break
    echo "attempt $attempt: the run ended before the kill (exit $rc); trying again"
  done
  ((rc == 137)) || fail "the run ended before the kill in five attempts (exit $rc): nothing was tested"
  for t in $(timeFolders "$c"); do  # every visible time folder is whole
    [[ -f $c/$t/uniform/frictionState && -f $c/$t/D ]] || fail "time folder $t is not whole"
  done
  echo "killed at random after time $(timeFolders "$c" | tail -1); restarting"
  restartAndCompare "$c"
  ;;
sigterm | sigint)
  sig=${scenario#sig}; sig=${sig^^}
  steps=40
  reference $steps
  makeCase "$work/stopped" $steps
  c=$work/stopped/case
  "$bin/frictionSolver" -case "$c" >"$c/log.1" 2>&1 &
  pid=$!
  for _ in $(seq 1000); do [[ -n $(timeFolders "$c") ]] && break; sleep 0.002; done
  kill -"$sig" $pid
  wait $pid
  rc=$?
  grep -q "Stopped at time" "$c/log.1" || fail "the run ended before SIG$sig (exit $rc): nothing was tested"
  ((rc == 5)) || fail "exit code $rc after SIG$sig, expected 5"
  grep -q "SIG$sig" "$c/log.1" || fail "no SIG$sig message"
  stopped=$(sed -n 's/.*Stopped at time \([^ ]*\) .*/\1/p' "$c/log.1")
  [[ -f $c/$stopped/uniform/frictionState ]] || fail "the step at $stopped was not written"
  echo "stopped at time $stopped; restarting"
  # The stop wrote its step; if the schedule does not, that time is the one extra.
  extra=$stopped
  [[ -d $work/reference/case/$stopped ]] && extra=
  restartAndCompare "$c" "$extra"
  ;;
parallelKill)
  # 2 ranks (mumps): rank 0, the one that writes, killed with SIGKILL as soon as a few time
  # folders exist; mpirun then ends the other rank. The restart on 2 ranks leaves every file as
  # the uninterrupted 2-rank run does.
  steps=40
  reference $steps
  makeCase "$work/killed" $steps
  c=$work/killed/case
  solve "$c" "$c/log.1" &
  for _ in $(seq 4000); do (($(timeFolders "$c" | wc -l) >= 3)) && break; sleep 0.002; done
  # Rank 0: the solver process whose log is the case's (the other's output is discarded);
  # among mpirun's children, the one with the smallest OMPI_COMM_WORLD_RANK.
  victim=
  for p in $(pgrep -f "frictionSolver -parallel -case $c"); do
    [[ -r /proc/$p/environ ]] || continue
    tr '\0' '\n' <"/proc/$p/environ" | grep -qx "OMPI_COMM_WORLD_RANK=0" && victim=$p
  done
  [[ -n $victim ]] || fail "rank 0 not found: nothing was tested"
  kill -KILL "$victim"
  wait
  (($(timeFolders "$c" | wc -l) < steps / 5)) || fail "the run ended before the kill: nothing was tested"
  sleep 1
  [[ -z $(pgrep -f "frictionSolver -parallel -case $c") ]] || fail "a rank outlived the kill of rank 0"
  for t in $(timeFolders "$c"); do
    [[ -f $c/$t/uniform/frictionState && -f $c/$t/D ]] || fail "time folder $t is not whole"
  done
  echo "rank 0 killed after time $(timeFolders "$c" | tail -1); restarting on 2 ranks"
  restartAndCompare "$c"
  ;;
parallelSigterm)
  # SIGTERM to both ranks (as a batch system signals the tasks of a job): they finish and
  # write the step together (exit 5); the restart completes the run as the uninterrupted 2-rank
  # run. (A SIGTERM to mpirun itself makes OpenMPI 4 end the job by killing its ranks: that is
  # parallelKill's case.)
  steps=200  # a run long enough to be signalled in the middle
  reference $steps
  makeCase "$work/stopped" $steps
  c=$work/stopped/case
  solve "$c" "$c/log.1" &
  pid=$!
  for _ in $(seq 4000); do [[ -n $(timeFolders "$c") ]] && break; sleep 0.002; done
  ranks=$(pgrep -f "^$bin/frictionSolver -parallel -case $c")
  [[ $(wc -w <<<"$ranks") == 2 ]] || fail "expected 2 ranks, found: $ranks"
  kill -TERM $ranks
  wait $pid
  rc=$?
  ((rc == 5)) || fail "exit code $rc after SIGTERM, expected 5: $(tail -5 "$c/log.1")"
  stopped=$(sed -n 's/.*Stopped at time \([^ ]*\) .*/\1/p' "$c/log.1")
  [[ -n $stopped && -f $c/$stopped/uniform/frictionState ]] ||
    fail "the step at '$stopped' was not written: $(tail -5 "$c/log.1")"
  (($(timeFolders "$c" | wc -l) < steps / 5)) || fail "the run ended before the signal: nothing was tested"
  echo "stopped at time $stopped; restarting on 2 ranks"
  extra=$stopped
  [[ -d $work/reference/case/$stopped ]] && extra=
  restartAndCompare "$c" "$extra"
  ;;
parallelStuckSigterm)
  # 2 ranks, one of which cannot come to a shared call: rank 0 stopped (SIGSTOP) while rank 1
  # goes on to the next shared solve and waits for it there. (An output error on rank 0 used
  # to make this state, and SIGTERM then changed nothing; parallel.outputErrors shows that it
  # no longer arises, and this is the nearest state a run can still be in.) Two SIGTERMs to the
  # waiting rank must end the run, every rank, with exit 5, within seconds; the time folders
  # written are whole, and the restart on 2 ranks completes the run as the uninterrupted one.
  steps=40
  reference $steps
  makeCase "$work/stuck" $steps
  c=$work/stuck/case
  timeout 60 "${launcher[@]}" "$bin/frictionSolver" -parallel -case "$c" >"$c/log.1" 2>&1 &
  pid=$!
  for _ in $(seq 4000); do [[ -n $(timeFolders "$c") ]] && break; sleep 0.002; done
  writer= waiter=
  for p in $(pgrep -f "^$bin/frictionSolver -parallel -case $c"); do
    if tr '\0' '\n' <"/proc/$p/environ" | grep -qx "OMPI_COMM_WORLD_RANK=0"; then writer=$p; else waiter=$p; fi
  done
  [[ -n $writer && -n $waiter ]] || fail "the 2 ranks not found: nothing was tested"
  kill -STOP "$writer"
  sleep 0.5  # rank 1 reaches the next shared call
  kill -TERM "$waiter"
  sleep 0.3
  kill -TERM "$waiter"
  start=$SECONDS
  wait $pid
  rc=$?
  kill -CONT "$writer" 2>/dev/null
  ((rc != 124)) || { kill -KILL "$writer" "$waiter" 2>/dev/null; fail "the run went on 60 s after two SIGTERMs: $(tail -5 "$c/log.1")"; }
  ((rc == 5)) || fail "exit code $rc after two SIGTERMs, expected 5: $(tail -5 "$c/log.1")"
  sleep 1
  [[ -z $(pgrep -f "frictionSolver -parallel -case $c") ]] || fail "a rank outlived the stop"
  (($(timeFolders "$c" | wc -l) < steps / 5)) || fail "the run ended before the signals: nothing was tested"
  for t in $(timeFolders "$c"); do
    [[ -f $c/$t/uniform/frictionState && -f $c/$t/D ]] || fail "time folder $t is not whole"
  done
  echo "ended $((SECONDS - start)) s after the second SIGTERM, after time $(timeFolders "$c" | tail -1); restarting on 2 ranks"
  # mpirun ends the stopped rank 0 with SIGCONT and SIGTERM before SIGKILL: resumed, it may
  # finish its step and write that time as a first signal asks (a stop by signal adds its own
  # time folder, whole: checked above), which the uninterrupted run does not write.
  stopped=$(timeFolders "$c" | tail -1)
  extra=$stopped
  [[ -d $work/reference/case/$stopped ]] && extra=
  restartAndCompare "$c" "$extra"
  ;;
diskFull)
  [[ $(id -u) -eq 0 ]] || fail "needs root to mount a small tmpfs"
  reference 40 1
  mkdir -p "$work/small"
  # Room for two or three written times (a .vtu is 750 kB) before the disk is full.
  mount -t tmpfs -o size=3m tmpfs "$work/small" || fail "cannot mount a tmpfs"
  trap 'umount "$work/small" 2>/dev/null' EXIT
  # 1. The time folders fill the disk.
  makeCase "$work/small" 40
  c=$work/small/case
  setKey "$c" writeInterval 1
  # The mesh stays: frictionSolver checks that constant/splitMesh was made from it.
  solve "$c" "$work/small.log"
  ((rc == 6)) || fail "exit code $rc on a full disk, expected 6: $(tail -3 "$work/small.log")"
  grep -q "error" "$work/small.log" || fail "no error message"
  grep -q "$c" "$work/small.log" || fail "the message does not name the file"
  folders=$(timeFolders "$c")
  [[ -n $folders ]] || fail "no time folder fitted: the test tests nothing"
  # VTK files and .pvd entries are those of the time folders, whole.
  vtus=$(cd "$c/VTK" && ls case_*.vtu | sed 's/^case_//; s/\.vtu$//' | sort -g)
  [[ $vtus == "$folders" ]] || fail "VTK files of times $(echo $vtus), time folders $(echo $folders)"
  pvd=$(sed -n 's/.*file="case_\(.*\)\.vtu".*/\1/p' "$c/VTK/case.pvd" | sort -g)
  [[ $pvd == "$folders" ]] || fail "the .pvd lists times $(echo $pvd), time folders $(echo $folders)"
  for t in $folders; do
    cmp -s "$work/reference/case/VTK/case_$t.vtu" "$c/VTK/case_$t.vtu" || fail "VTK/case_$t.vtu damaged"
  done
  for t in $folders; do
    for f in D fractures/fracture.dat uniform/frictionState; do
      cmp -s "$work/reference/case/$t/$f" "$c/$t/$f" || fail "time $t: $f damaged"
    done
  done
  [[ -z $(cd "$c" && find . -name '.?*') ]] || fail "leftovers: $(cd "$c" && find . -name '.?*')"
  echo "full disk after times: $(echo $folders)"
  # 2. convergence.dat fills the disk: many steps, nothing else written until the end.
  rm -rf "$c"
  makeCase "$work/small" 2000
  setKey "$c" writeInterval 100000
  echo "writeVTK no;" >>"$c/system/controlDict"
  # The mesh stays: frictionSolver checks that constant/splitMesh was made from it.
  mkdir -p "$c/postProcessing"
  free=$(df --output=avail -B1 "$work/small" | tail -1)
  # Leave a few pages: the history (a few hundred bytes a step) overflows them mid-run.
  head -c $((free - 4 * 4096)) /dev/zero >"$work/small/filler" 2>/dev/null
  solve "$c" "$work/small.log"
  ((rc == 6)) || fail "convergence.dat: exit code $rc on a full disk, expected 6: $(tail -3 "$work/small.log")"
  grep -q "postProcessing/convergence.dat" "$work/small.log" || fail "the message does not name convergence.dat: $(tail -2 "$work/small.log")"
  h=$c/postProcessing/convergence.dat
  [[ $(wc -l <"$h") -gt 10 ]] || fail "convergence.dat got nothing before the disk was full: nothing was tested"
  [[ $(tail -c 1 "$h" | od -An -c | tr -d ' ') == '\n' ]] || fail "convergence.dat ends mid-line"
  awk '!/^#/ && NF != 5 { exit 1 }' "$h" || fail "convergence.dat has a cut line"
  echo "convergence.dat full after $(wc -l <"$h") lines"
  ;;
overwrite)
  reference 20
  makeCase "$work/again" 20
  c=$work/again/case
  solve "$c" "$c/log.1"
  ((rc == 0)) || fail "first run failed"
  # What is not the solver's stays: a note in postProcessing, the 0 folder.
  echo "my notes" >"$c/postProcessing/notes.txt"
  before=$(cd "$c" && find . -type f ! -name 'log.*' -exec md5sum {} + | sort)
  solve "$c" "$c/log.2"
  ((rc == 1)) || fail "a second run over the time folders: exit $rc, expected 1"
  for e in "$c" "0.25, 0.5, 0.75, 1" "startFrom latestTime" "-overwrite"; do
    grep -qF -- "$e" "$c/log.2" || fail "the refusal does not say '$e': $(tail -2 "$c/log.2")"
  done
  [[ $(cd "$c" && find . -type f ! -name 'log.*' -exec md5sum {} + | sort) == "$before" ]] ||
    fail "the refused run changed files"
  # -overwrite: a stale time folder of another deltaT goes too; the result is a clean run's.
  cp -r "$c/0.5" "$c/0.55"
  solve "$c" "$c/log.3" -overwrite
  ((rc == 0)) || fail "-overwrite failed (exit $rc): $(tail -3 "$c/log.3")"
  grep -q "overwrite: removed" "$c/log.3" || fail "-overwrite does not say what it removed"
  [[ $(cat "$c/postProcessing/notes.txt") == "my notes" ]] || fail "-overwrite removed a file not the solver's"
  rm "$c/postProcessing/notes.txt"
  sameOutputs "$work/reference/case" "$c"
  ;;
heldLoads)
  # Loads held after t = 0.5: the steps after it reuse 0.5's solution ("loads unchanged").
  # Restarted from 0.5 (the last solved step) and from 0.75 (itself a reused step), the run
  # reuses as the uninterrupted one does: it makes the recorded state again (the restore
  # entry of uniform/frictionState) instead of solving again from the trial state, and every
  # output file is the uninterrupted run's, byte for byte. With Coulomb friction and with
  # slip-weakening (whose state, the slip path, and patch stiffness the restore entry adds).
  held() {  # held CASE LAW
    sed -i 's/(1 (-0.02 -0.025))/(0.5 (-0.02 -0.025))/' "$1/0/D"
    grep -q "(0.5 (-0.02" "$1/0/D" || fail "cannot hold the load"
    setKey "$1" writeInterval 1
    if [[ $2 == slipWeakening ]]; then
      sed -i 's/^ *law  *coulomb;/    law slipWeakening; staticCoefficient 0.2; dynamicCoefficient 0.18; criticalSlip 0.01;/; /^ *frictionCoefficient/d' \
        "$1/constant/fractureProperties"
      grep -q "law slipWeakening" "$1/constant/fractureProperties" || fail "cannot set slipWeakening"
    fi
  }
  for law in coulomb slipWeakening; do
    rm -rf "$work/reference" "$work"/stop*
    makeCase "$work/reference" 8
    held "$work/reference/case" $law
    solve "$work/reference/case" "$work/reference/case/log.frictionSolver"
    ((rc == 0)) || fail "$law: reference run failed: $(tail -3 "$work/reference/case/log.frictionSolver")"
    reused=$(grep -c "loads unchanged: previous solution reused" "$work/reference/case/log.frictionSolver")
    ((reused == 4)) || fail "$law: the reference reused $reused steps, expected 4 (0.625 to 1)"
    for stop in 0.5 0.75; do
      makeCase "$work/stop$stop" 8
      c=$work/stop$stop/case
      held "$c" $law
      setKey "$c" endTime $stop
      solve "$c" "$c/log.1"
      ((rc == 0)) || fail "$law: first part to $stop failed"
      grep -q "^ *restore$" "$c/$stop/uniform/frictionState" || fail "$law, $stop: no restore entry in the state"
      setKey "$c" endTime 1
      restartAndCompare "$c"
      grep -q "^Time = 0.875  loads unchanged: previous solution reused  iterations 0  backSubstitutions 0 " "$c/log.2" ||
        fail "$law: restarted from $stop: 0.875 not reused: $(grep -a '^Time = 0.875' "$c/log.2")"
      echo "$law, restarted from $stop: every output as the uninterrupted run's"
    done
  done
  ;;
changedDeltaT)
  # Continue from the saved time with another deltaT, or to a later endTime: the times go
  # on from 0.5 and the last step ends at 1. The load is proportional and the slip only
  # grows, so the end state does not depend on the steps (to the solver tolerance).
  reference 10 1
  for dt in 0.05 0.25 0.3 0.1; do
    makeCase "$work/dt$dt" 10
    c=$work/dt$dt/case
    setKey "$c" writeInterval 1
    setKey "$c" endTime 0.5
    solve "$c" "$c/log.1"
    ((rc == 0)) || fail "first half failed"
    setKey "$c" endTime 1
    setKey "$c" deltaT "$dt"
    setKey "$c" startFrom latestTime
    solve "$c" "$c/log.2"
    ((rc == 0)) || fail "deltaT $dt: restart failed (exit $rc): $(tail -3 "$c/log.2")"
    times=$(sed -n 's/^Time = \([^ ]*\) .*/\1/p' "$c/log.2" | tr '\n' ' ')
    expected=$(awk -v dt="$dt" 'BEGIN { for (t = 0.5 + dt; t < 1 - 1e-9; t += dt) printf "%.10g ", t; print "1 " }')
    [[ $times == "$expected" ]] || fail "deltaT $dt: restarted times '$times', expected '$expected'"
    /usr/bin/python3 - "$work/reference/case/1/fractures/fracture.dat" "$c/1/fractures/fracture.dat" <<'PY' || fail "deltaT $dt: the slip at time 1 differs"
import sys
rows = [[float(l.split()[3]) for l in open(p) if not l.startswith('#')] for p in sys.argv[1:]]
a, b = rows
big = max(abs(x) for x in a)
# 1e-6 of the largest slip: far above the solver tolerance (residual 1e-10), far below
# the slip a step too many or too few adds (a tenth of it).
assert len(a) == len(b) > 10 and big > 0
err = max(abs(x - y) for x, y in zip(a, b))
print("deltaT restart: max slip difference %.3g of max slip %.3g" % (err, big))
sys.exit(0 if err <= 1e-6 * big else 1)
PY
  done
  # A later endTime with the same deltaT is the uninterrupted run, file for file.
  sameOutputs "$work/reference/case" "$work/dt0.1/case"
  ;;
timeArithmetic)
  # A deltaT that makes 1e10 steps is refused by name (it wrapped a counter into one step).
  makeCase "$work/tiny" 10
  c=$work/tiny/case
  setKey "$c" deltaT 1e-10
  solve "$c" "$c/log.frictionSolver"
  ((rc == 1)) || fail "deltaT 1e-10: exit $rc, expected 1: $(tail -2 "$c/log.frictionSolver")"
  grep -q "system/controlDict:[0-9]*: key 'deltaT'" "$c/log.frictionSolver" || fail "deltaT 1e-10: the message does not name controlDict's deltaT"
  [[ -z $(timeFolders "$c") ]] || fail "deltaT 1e-10: time folders written"
  # Names that timePrecision would make collide get more digits (and the log says so): one
  # folder per step, each holding the state of its own time.
  for keys in "deltaT 0.05|timePrecision 1|endTime 1|startTime 0" \
              "deltaT 0.1|timePrecision 6|endTime 100001|startTime 100000"; do
    makeCase "$work/names" 10
    c=$work/names/case
    setKey "$c" writeInterval 1
    IFS='|' read -ra kv <<<"$keys"
    for k in "${kv[@]}"; do
      grep -q "^${k%% *} " "$c/system/controlDict" || echo "${k%% *} 0;" >>"$c/system/controlDict"
      setKey "$c" "${k%% *}" "${k#* }"
    done
    solve "$c" "$c/log.frictionSolver"
    ((rc == 0)) || fail "[$keys] exit $rc: $(tail -2 "$c/log.frictionSolver")"
    grep -q "timePrecision raised to" "$c/log.frictionSolver" || fail "[$keys] the log does not say timePrecision was raised"
    steps=$(grep -c "^Time = " "$c/log.frictionSolver")
    folders=$(timeFolders "$c" | grep -vx "${kv[3]#* }")
    (($(wc -l <<<"$folders") == steps)) || fail "[$keys] $steps steps, folders: $(echo $folders)"
    for t in $folders; do  # each folder is its own time's
      saved=$(sed -n 's/^time *\([^;]*\);/\1/p' "$c/$t/uniform/frictionState")
      awk -v a="$t" -v b="$saved" 'BEGIN { d = a - b; exit !(d < 1e-9 && d > -1e-9) }' ||
        fail "[$keys] folder $t holds the state of time $saved"
    done
    echo "[$keys] $steps steps, $steps folders: $(echo $folders | cut -c1-60)..."
    rm -rf "$work/names"
  done
  ;;
foreignFolders)
  # Nothing the solver did not write is removed or replaced (issue 26, 7): a user's folder
  # under a time's name after the newest complete time (a restart would write over it), a
  # user's file in a solver's time folder (-overwrite would remove it). Both are refused, named,
  # and the case is left as it was; a user's folder before the restart time, and a file in the
  # folder the restart starts from, stay where they are while the run goes on.
  makeCase "$work/user" 8
  c=$work/user/case
  setKey "$c" writeInterval 1
  setKey "$c" endTime 0.5
  solve "$c" "$c/log.1"
  ((rc == 0)) || fail "first half failed: $(tail -3 "$c/log.1")"
  setKey "$c" endTime 1
  setKey "$c" startFrom latestTime
  # After the newest complete time: the next time's name with notes, and an empty folder.
  mkdir "$c/0.625" "$c/0.75"
  echo notes >"$c/0.625/notes.txt"
  datedBack
  before=$(snapshot)
  solve "$c" "$c/log.2"
  ((rc == 1)) || fail "a user's folder after the restart time: exit $rc, expected 1: $(tail -2 "$c/log.2")"
  for e in "$c/0.625" "0.625, 0.75" "notes.txt" "no uniform/frictionState" "move them out"; do
    grep -qF -- "$e" "$c/log.2" || fail "the refusal does not say '$e': $(tail -2 "$c/log.2")"
  done
  [[ $(snapshot) == "$before" ]] || fail "the refused restart changed the case"
  # -overwrite does not remove them either (one error names the folder and its file).
  solve "$c" "$c/log.3" -overwrite
  ((rc == 1)) || fail "-overwrite over a user's folder: exit $rc, expected 1: $(tail -2 "$c/log.3")"
  grep -qF "$c/0.625: not removed by frictionSolver -overwrite" "$c/log.3" &&
    grep -qF "notes.txt" "$c/log.3" || fail "-overwrite's refusal does not name the folder and file: $(tail -2 "$c/log.3")"
  [[ $(snapshot) == "$before" ]] || fail "the refused -overwrite changed the case"
  rmdir "$c/0.75"
  mv "$c/0.625/notes.txt" "$c/0.25/notes.txt"
  rmdir "$c/0.625"
  # A user's file in a solver's time folder: -overwrite refuses, naming the file.
  datedBack
  before=$(snapshot)
  solve "$c" "$c/log.4" -overwrite
  ((rc == 1)) || fail "-overwrite over a user's file: exit $rc, expected 1: $(tail -2 "$c/log.4")"
  grep -qF "$c/0.25: not removed" "$c/log.4" && grep -qF "'notes.txt'" "$c/log.4" ||
    fail "-overwrite's refusal does not name 0.25 and notes.txt: $(tail -2 "$c/log.4")"
  [[ $(snapshot) == "$before" ]] || fail "the refused -overwrite changed the case"
  # Before the restart time: a user's folder (0.3) and a file in the folder restarted from.
  mkdir "$c/0.3"
  echo notes >"$c/0.3/notes.txt"
  echo notes >"$c/0.5/notes.txt"
  solve "$c" "$c/log.5"
  ((rc == 0)) || fail "a restart with a user's folder before it: exit $rc: $(tail -2 "$c/log.5")"
  [[ -f $c/1/uniform/frictionState ]] || fail "the restart did not reach time 1"
  for f in 0.3 0.25 0.5; do
    [[ $(cat "$c/$f/notes.txt") == notes ]] || fail "$f/notes.txt is gone"
  done
  ;;
restartMismatch)
  # A restart from a folder whose name is not the time of its state is refused (issue 26, 5);
  # an endTime at or before the saved time computes and rewrites nothing; a case continued in a
  # copy under another folder name keeps one ParaView series.
  reference 8 1
  makeCase "$work/copied" 8
  c=$work/copied/case
  setKey "$c" writeInterval 1
  setKey "$c" endTime 0.5
  solve "$c" "$c/log.1"
  ((rc == 0)) || fail "first half failed: $(tail -3 "$c/log.1")"
  setKey "$c" endTime 1
  setKey "$c" startFrom latestTime
  # 1. An earlier time copied to a later name (cp -r 0.25 0.75), and the newest folder's state
  # edited to an earlier time: both refused, naming the folder, the time recorded and the way out.
  cp -r "$c/0.25" "$c/0.75"
  datedBack "$c"
  before=$(snapshot "$c")
  solve "$c" "$c/log.2"
  ((rc == 1)) || fail "a copied time folder: exit $rc, expected 1: $(tail -2 "$c/log.2")"
  for e in "$c/0.75/uniform/frictionState" "time 0.25 (step 2)" "folder's time 0.75" "Remove the folder 0.75"; do
    grep -qF -- "$e" "$c/log.2" || fail "the refusal does not say '$e': $(tail -2 "$c/log.2")"
  done
  [[ $(snapshot "$c") == "$before" ]] || fail "the refused restart changed the case"
  rm -rf "$c/0.75"
  cp "$c/0.5/uniform/frictionState" "$work/state"
  sed -i 's/^time .*/time 0.375;/' "$c/0.5/uniform/frictionState"
  solve "$c" "$c/log.3"
  ((rc == 1)) || fail "a state of another time: exit $rc, expected 1: $(tail -2 "$c/log.3")"
  grep -qF "$c/0.5/uniform/frictionState" "$c/log.3" && grep -qF "time 0.375" "$c/log.3" ||
    fail "the refusal does not name 0.5 and time 0.375: $(tail -2 "$c/log.3")"
  cp "$work/state" "$c/0.5/uniform/frictionState"
  # 2. endTime before the saved time, or at it: nothing to compute, said why, nothing rewritten.
  for end in 0.375 0.5; do
    setKey "$c" endTime $end
    datedBack "$c"
    before=$(snapshot "$c")
    solve "$c" "$c/log.4"
    ((rc == 0)) || fail "endTime $end below the saved time: exit $rc, expected 0: $(tail -2 "$c/log.4")"
    grep -qF "nothing is left to compute: endTime $end (system/controlDict) is at or before the saved time 0.5; raise endTime" "$c/log.4" ||
      fail "endTime $end: the log does not say why nothing is computed: $(grep Restarting "$c/log.4")"
    ! grep -q "^Time = " "$c/log.4" || fail "endTime $end: steps were computed"
    [[ $(snapshot "$c") == "$before" ]] || fail "endTime $end: files were rewritten"
  done
  setKey "$c" endTime 1
  # 3. Continued in a copy named otherwise: the series goes on under its first name (the log
  # says so), and the outputs are the uninterrupted run's, one .pvd with every time.
  mkdir -p "$work/renamed"
  cp -r "$c" "$work/renamed/copy"
  rm "$work/renamed/copy"/log.*
  solve "$work/renamed/copy" "$work/renamed/copy/log.frictionSolver"
  ((rc == 0)) || fail "the renamed copy's restart failed: $(tail -2 "$work/renamed/copy/log.frictionSolver")"
  grep -qF "VTK: the earlier times are in VTK/case.pvd" "$work/renamed/copy/log.frictionSolver" ||
    fail "the log does not say under which name the VTK series goes on"
  [[ -z $(ls "$work/renamed/copy/VTK" | grep copy) ]] || fail "VTK files under the copy's name: $(ls "$work/renamed/copy/VTK")"
  sameOutputs "$work/reference/case" "$work/renamed/copy"
  ;;
caseLock)
  # One run at a time in a case (issue 26, 6): a lock held by a living process refuses the
  # run before anything is written or removed (-overwrite included), naming the owner; one
  # left by a process that is gone is taken over; it is removed at the end, on SIGTERM before
  # the time loop and within it. Two real runs: the second is refused while the first lives.
  reference 20
  makeCase "$work/locked" 20
  c=$work/locked/case
  solve "$c" "$c/log.1"
  ((rc == 0)) || fail "first run failed"
  [[ ! -e $c/.frictionSolver.lock ]] || fail "the lock outlived the run"
  # 1. Held by a living process of this host (a sleeping one), or a process of another host.
  sleep 300 >/dev/null 2>&1 &
  holder=$!
  trap 'kill $holder 2>/dev/null' EXIT
  for owner in "$holder $(hostname) frictionSolver" "4242 elsewhere.example frictionSolver"; do
    echo "$owner" >"$c/.frictionSolver.lock"
    datedBack
    before=$(snapshot)
    solve "$c" "$c/log.2" -overwrite
    ((rc == 1)) || fail "[$owner] a locked case: exit $rc, expected 1: $(tail -2 "$c/log.2")"
    grep -qF "$c/.frictionSolver.lock" "$c/log.2" && grep -qF "process ${owner%% *} on host" "$c/log.2" ||
      fail "[$owner] the refusal does not name the lock and its owner: $(tail -2 "$c/log.2")"
    [[ $(snapshot) == "$before" ]] || fail "[$owner] the refused run changed the case (-overwrite removed files?)"
  done
  # 2. The holder is gone: taken over, and the run goes on.
  kill $holder
  wait $holder 2>/dev/null
  echo "$holder $(hostname) frictionSolver" >"$c/.frictionSolver.lock"
  solve "$c" "$c/log.3" -overwrite
  ((rc == 0)) || fail "a stale lock: exit $rc, expected 0: $(tail -2 "$c/log.3")"
  grep -qF "was left by frictionSolver (process $holder" "$c/log.3" && grep -qF "taken over" "$c/log.3" ||
    fail "the log does not say the stale lock was taken over"
  [[ ! -e $c/.frictionSolver.lock ]] || fail "the lock outlived the run"
  sameOutputs "$work/reference/case" "$c"
  # 3. Two real runs: the second starts while the first (stopped by SIGSTOP once it holds the
  # lock, so that it cannot end first) lives; it is refused, and the first ends as a clean run.
  "$bin/frictionSolver" -case "$c" -overwrite >"$c/log.4" 2>&1 &
  first=$!
  for _ in $(seq 1000); do grep -q "^$first " "$c/.frictionSolver.lock" 2>/dev/null && break; sleep 0.005; done
  kill -STOP $first
  grep -q "^$first " "$c/.frictionSolver.lock" || { kill -KILL $first; fail "the first run never held the lock"; }
  solve "$c" "$c/log.5" -overwrite
  rcSecond=$rc
  kill -CONT $first
  wait $first
  rcFirst=$?
  ((rcSecond == 1)) || fail "the second run: exit $rcSecond, expected 1: $(tail -2 "$c/log.5")"
  grep -qF "is running in it" "$c/log.5" && grep -qF "process $first on host" "$c/log.5" ||
    fail "the second run's refusal does not name the first: $(tail -2 "$c/log.5")"
  ((rcFirst == 0)) || fail "the first run: exit $rcFirst: $(tail -2 "$c/log.4")"
  sameOutputs "$work/reference/case" "$c"
  # 4. SIGTERM as soon as the lock is taken (before the time loop, or within it) and SIGKILL:
  # the lock goes with the run, or is taken over by the next.
  for sig in TERM KILL; do
    "$bin/frictionSolver" -case "$c" -overwrite >"$c/log.6" 2>&1 &
    pid=$!
    for _ in $(seq 1000); do grep -q "^$pid " "$c/.frictionSolver.lock" 2>/dev/null && break; sleep 0.001; done
    kill -$sig $pid
    wait $pid
    rc=$?
    ((rc != 0)) || fail "SIG$sig: the run ended before the signal: nothing was tested"
    if [[ $sig == TERM ]]; then
      [[ ! -e $c/.frictionSolver.lock ]] || fail "SIGTERM (exit $rc): the lock outlived the run"
    else
      [[ -e $c/.frictionSolver.lock ]] || fail "SIGKILL: no lock left: nothing was tested"
    fi
  done
  solve "$c" "$c/log.7" -overwrite
  ((rc == 0)) || fail "after SIGKILL: exit $rc: $(tail -2 "$c/log.7")"
  grep -qF "taken over" "$c/log.7" || fail "after SIGKILL: the lock was not taken over"
  sameOutputs "$work/reference/case" "$c"
  ;;
parallelLock)
  # On 2 ranks rank 0 holds the lock; a locked case ends both ranks with exit 1 and one
  # message, at once (no rank waits for the other).
  makeCase "$work/locked" 10
  c=$work/locked/case
  sleep 300 >/dev/null 2>&1 &
  holder=$!
  trap 'kill $holder 2>/dev/null' EXIT
  echo "$holder $(hostname) frictionSolver" >"$c/.frictionSolver.lock"
  timeout 60 "${launcher[@]}" "$bin/frictionSolver" -parallel -case "$c" >"$c/log.1" 2>&1
  rc=$?
  kill $holder
  ((rc == 1)) || fail "a locked case on 2 ranks: exit $rc, expected 1: $(tail -3 "$c/log.1")"
  (($(grep -c "is running in it" "$c/log.1") == 1)) || fail "expected one refusal: $(cat "$c/log.1")"
  [[ -z $(timeFolders "$c") ]] || fail "time folders written"
  rm "$c/.frictionSolver.lock"
  solve "$c" "$c/log.2"
  ((rc == 0)) || fail "the unlocked case on 2 ranks: exit $rc: $(tail -3 "$c/log.2")"
  [[ ! -e $c/.frictionSolver.lock ]] || fail "the lock outlived the run"
  ;;
logFlushed)
  # The log reaches a file line by line as it is written, not when the C library's buffer
  # fills or the run ends: killed (SIGKILL, which flushes nothing) as the first time folder is
  # committed, the run has left every line before it in the file — the setup phases with their
  # times among them (about 2 KB: the whole log stayed in the buffer before). Killed at the
  # second folder, the first step's line is there, with the fields after the progress.
  [[ -f $killLib ]] || fail "no kill library given"
  for n in 1 2; do
    makeCase "$work/kill$n" 4
    c=$work/kill$n/case
    setKey "$c" writeInterval 1
    FRICTION_KILL_AT_RENAME=".partial -> |$n" LD_PRELOAD=$preload "$bin/frictionSolver" -case "$c" >"$c/log.1" 2>&1
    rc=$?
    ((rc == 137)) || fail "[$n] not killed (exit $rc): nothing was tested"
    for line in "frictionSolver, started " "Setup: case and split mesh read (" \
      "Setup: numeric factorisation (CHOLMOD" "Setup: interface operator S, the complement of the" \
      "Interface operator: " "Split mesh: " "Setup: Newton's interface operator in the fractures' frame"; do
      grep -qF "$line" "$c/log.1" || fail "[$n] killed at time folder $n, the log lacks '$line': $(cat "$c/log.1")"
    done
    steps=$(grep -c "^Time = " "$c/log.1")
    ((steps == n - 1)) || fail "[$n] killed at time folder $n: $steps step lines, expected $((n - 1))"
  done
  grep -qE '^Time = 0.25 .*  \[step 1/4, [0-9.e+-]+ s\]  maxSlip [0-9.e+-]+ m  loadDisplacement 0.008004 m  \[[0-9.e+-]+ s\]$' "$c/log.1" ||
    fail "the first step's line: $(grep '^Time = ' "$c/log.1")"
  ;;
*) fail "unknown scenario" ;;
esac
echo "PASS [$scenario]"
