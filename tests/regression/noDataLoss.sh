#!/usr/bin/env bash
# No data loss (issue: hard cases / kills): a run killed with SIGKILL and restarted with
# startFrom latestTime ends with the same fields, bit for bit, as an uninterrupted run;
# SIGTERM finishes the current step, writes it and exits with a message; a full disk gives
# a clear error and leaves earlier time folders intact.
# Usage: noDataLoss.sh BIN_DIR SOURCE_DIR WORK_DIR SCENARIO
set -uo pipefail
bin=$1 src=$2 work=$3 scenario=$4
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL [$scenario]: $*"; exit 1; }

# The paper benchmark ramped over many small steps, written every 10 steps.
makeCase() {  # makeCase DIR STEPS
  # Clean a copy outside the target first: what an earlier ./Allrun left in cases/ must not
  # come along (nor fill the small tmpfs of diskFull before it is cleaned).
  local stage="$work/stage.$RANDOM"
  cp -r "$src/cases/paperBenchmark" "$stage"
  "$stage/Allclean" >/dev/null
  mv "$stage" "$1"
  sed -i "s/^deltaT .*/deltaT          $(awk -v n="$2" 'BEGIN{printf "%.10g", 1/n}');/; s/^writeInterval .*/writeInterval   10;/" \
    "$1/system/controlDict"
  "$bin/splitFractureNodes" -case "$1" >"$1/log.splitFractureNodes" 2>&1 || fail "split failed"
}
timeFolders() { (cd "$1" && ls -d [0-9]* 2>/dev/null | grep -vx 0 | sort -g); }

case $scenario in
killRestart)
  steps=400
  makeCase "$work/reference" $steps
  "$bin/frictionSolver" -case "$work/reference" >"$work/reference/log.frictionSolver" 2>&1 ||
    fail "reference run failed"
  makeCase "$work/killed" $steps
  "$bin/frictionSolver" -case "$work/killed" >"$work/killed/log.1" 2>&1 &
  pid=$!
  # Kill as soon as a few time folders exist (40 are written in all).
  for _ in $(seq 2000); do (($(timeFolders "$work/killed" | wc -l) >= 3)) && break; sleep 0.005; done
  kill -0 $pid 2>/dev/null || fail "the run ended before the kill: nothing was tested"
  kill -KILL $pid
  wait $pid 2>/dev/null
  folders=$(timeFolders "$work/killed")
  [[ -n $folders ]] || fail "no time folder written before the kill"
  last=$(tail -1 <<<"$folders")
  [[ $last != 1 ]] || fail "the run reached the end before the kill"
  # Every visible time folder is whole: it has its state file (written last).
  for t in $folders; do
    [[ -f $work/killed/$t/uniform/frictionState && -f $work/killed/$t/D ]] || fail "time folder $t is not whole"
  done
  echo "killed after time $last; restarting"
  sed -i 's/^startFrom .*/startFrom       latestTime;/' "$work/killed/system/controlDict"
  "$bin/frictionSolver" -case "$work/killed" >"$work/killed/log.2" 2>&1 || fail "restart failed: $(tail "$work/killed/log.2")"
  grep -q "Restarting from time $last" "$work/killed/log.2" || fail "did not restart from $last"
  for f in D fractures/fracture.dat uniform/frictionState solverStatus; do
    cmp -s "$work/reference/1/$f" "$work/killed/1/$f" || fail "1/$f differs from the uninterrupted run"
  done
  ;;
sigterm | sigint)
  sig=${scenario#sig}; sig=${sig^^}
  makeCase "$work/case" 400
  "$bin/frictionSolver" -case "$work/case" >"$work/case/log.frictionSolver" 2>&1 &
  pid=$!
  for _ in $(seq 100); do [[ -n $(timeFolders "$work/case") ]] && break; sleep 0.02; done
  kill -"$sig" $pid
  wait $pid
  rc=$?
  grep -q "Stopped at time" "$work/case/log.frictionSolver" ||
    { [[ -d $work/case/1 ]] && fail "the run ended before SIG$sig: nothing was tested"; }
  ((rc == 5)) || fail "exit code $rc after SIG$sig, expected 5"
  grep -q "SIG$sig" "$work/case/log.frictionSolver" || fail "no SIG$sig message"
  stopped=$(sed -n 's/.*Stopped at time \([^ ]*\) .*/\1/p' "$work/case/log.frictionSolver")
  [[ -f $work/case/$stopped/uniform/frictionState ]] || fail "the step at $stopped was not written"
  ;;
diskFull)
  [[ $(id -u) -eq 0 ]] || fail "needs root to mount a small tmpfs"
  makeCase "$work/reference" 40
  sed -i 's/^writeInterval .*/writeInterval   1;/' "$work/reference/system/controlDict"
  "$bin/frictionSolver" -case "$work/reference" >"$work/reference/log.frictionSolver" 2>&1 || fail "reference failed"
  mkdir -p "$work/small"
  mount -t tmpfs -o size=900k tmpfs "$work/small" || fail "cannot mount a tmpfs"
  trap 'umount "$work/small" 2>/dev/null' EXIT
  makeCase "$work/small/case" 40
  sed -i 's/^writeInterval .*/writeInterval   1;/' "$work/small/case/system/controlDict"
  # The mesh stays: frictionSolver checks that constant/splitMesh was made from it.
  "$bin/frictionSolver" -case "$work/small/case" >"$work/small.log" 2>&1
  rc=$?
  ((rc == 6)) || fail "exit code $rc on a full disk, expected 6 (an output error): $(tail -3 "$work/small.log")"
  grep -q "error" "$work/small.log" || fail "no error message"
  grep -q "$work/small/case" "$work/small.log" || fail "the message does not name the file"
  folders=$(timeFolders "$work/small/case")
  [[ -n $folders ]] || fail "no time folder fitted: the test tests nothing"
  for t in $folders; do
    for f in D fractures/fracture.dat uniform/frictionState; do
      cmp -s "$work/reference/$t/$f" "$work/small/case/$t/$f" || fail "time $t: $f damaged"
    done
  done
  ls -a "$work/small/case" | grep -q '\.partial$' && fail "a partial folder was left behind"
  echo "full disk after times: $(echo $folders)"
  ;;
*) fail "unknown scenario" ;;
esac
echo "PASS [$scenario]"
