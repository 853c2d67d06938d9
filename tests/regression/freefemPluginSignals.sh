#!/usr/bin/env bash
# Signals and the FreeFEM plug-in: frictionSolve runs inside FreeFem++, so it must neither
# keep FreeFEM's process from being stopped nor lose data.
#  1. SIGTERM during the run (cases/strikeSlipFault, eight steps, from a mesh3 made by its
#     block.edp): the step in progress is finished and written, as frictionSolver does; then
#     the script ends with a FreeFEM error saying so (exit 8, not a kill), every time folder
#     is whole, and a command-line restart (startFrom latestTime) ends with the same last
#     table as an uninterrupted command-line run.
#  2. SIGTERM after frictionSolve returned: FreeFem++ dies of it at once, as without the
#     plug-in (the solver's handlers are gone when the run is).
# Usage: freefemPluginSignals.sh BIN_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
bin=$(cd "$1" && pwd) src=$(cd "$2" && pwd) work=$3
rm -rf "$work" && mkdir -p "$work"
export FF_LOADPATH="$bin;/usr/lib/freefem++;./"
export FF_INCLUDEPATH=/usr/include/freefem++/idp

prepare() {  # prepare NAME: a clean strikeSlipFault with a script that hands its mesh3 over
  local d=$work/$1
  cp -r "$src/cases/strikeSlipFault" "$d"
  (cd "$d" && ./Allclean >/dev/null)
  sed -n '/^savemesh(Th, out);/q;p' "$d/constant/mesh/block.edp" >"$d/run.edp"
  cat >>"$d/run.edp" <<'EOF'
load "friction"
mesh3 Ths = frictionSplit(Th, ".", overwrite = true);
int s = frictionSolve(".", overwrite = true);
cout << "solved " << s << endl;
{ ofstream f("solved.txt"); f << s << endl; }   // FreeFEM's cout is flushed only at the end
real acc = 0;
for (int i = 0; i < 2000000000; ++i) acc += i;   // minutes: the script goes on after the run
cout << "loop done " << acc << endl;
EOF
}
waitFor() {  # waitFor FILE PATTERN SECONDS
  local i
  for ((i = 0; i < $3 * 10; ++i)); do
    grep -q "$2" "$1" 2>/dev/null && return 0
    sleep 0.1
  done
  return 1
}
endOf() {  # endOf PID SECONDS: wait for it to end, kill it if it does not; rc: its exit code
  local i
  rc=0
  for ((i = 0; i < $2 * 10; ++i)); do
    kill -0 "$1" 2>/dev/null || break
    sleep 0.1
  done
  if kill -0 "$1" 2>/dev/null; then
    kill -9 "$1"
    echo "FAIL: FreeFem++ still runs $2 s after SIGTERM" >&2
  fi
  wait "$1" || rc=$?
}

# 1. During the run.
prepare during
d=$work/during
(cd "$d" && exec FreeFem++ -nw -ns run.edp -nFault 20 -nSide 16 -nLayers 10 >log.FreeFem++ 2>&1) &
pid=$!
waitFor "$d/log.FreeFem++" "^Time = 2 " 120 || { kill -9 $pid; echo "FAIL: no step 2" >&2; exit 1; }
kill -TERM $pid
endOf $pid 120
tail -n 4 "$d/log.FreeFem++"
((rc == 8)) || { echo "FAIL: exit $rc, expected 8 (a FreeFEM error)" >&2; exit 1; }
grep -q "frictionSolve: error: stopped by SIGTERM after writing the current step" \
  "$d/log.FreeFem++" || { echo "FAIL: no stop message" >&2; exit 1; }
[[ -e $d/solved.txt ]] && { echo "FAIL: the script went on" >&2; exit 1; }
last=$(ls -d "$d"/[1-9]* | sed 's#.*/##' | sort -n | tail -1)
((last < 8)) || { echo "FAIL: the run was not stopped (last time $last)" >&2; exit 1; }
for t in $(seq 1 "$last"); do
  [[ -f $d/$t/fractures/fault.dat && -f $d/$t/uniform/frictionState ]] ||
    { echo "FAIL: time folder $t is not whole" >&2; exit 1; }
done
ls -a "$d" | grep -q '\.partial' && { echo "FAIL: a partial time folder is left" >&2; exit 1; }
# The command line continues it, and ends as an uninterrupted run does.
sed -i 's/^startFrom .*/startFrom       latestTime;/' "$d/system/controlDict"
"$bin/frictionSolver" -case "$d" >"$d/log.restart" 2>&1
full=$work/uninterrupted
cp -r "$d" "$full"
rm -rf "$full"/[1-9]* "$full/postProcessing" "$full/VTK" "$full"/log.*
sed -i 's/^startFrom .*/startFrom       startTime;/' "$full/system/controlDict"
"$bin/frictionSolver" -case "$full" >"$full/log.frictionSolver" 2>&1
cmp -s "$d/8/fractures/fault.dat" "$full/8/fractures/fault.dat" ||
  { echo "FAIL: the restarted run's last table differs from an uninterrupted run's" >&2; exit 1; }
echo "ok: SIGTERM at step $last: exit 8, the steps written, the restart ends as an uninterrupted run"

# 2. After the run.
prepare after
d=$work/after
(cd "$d" && exec FreeFem++ -nw -ns run.edp -nFault 6 -nSide 6 -nLayers 3 >log.FreeFem++ 2>&1) &
pid=$!
waitFor "$d/solved.txt" "0" 120 || { kill -9 $pid; echo "FAIL: frictionSolve did not return 0" >&2; exit 1; }
sleep 0.3
kill -TERM $pid
endOf $pid 10
((rc == 143)) || { echo "FAIL: exit $rc after the run, expected 143 (killed by SIGTERM)" >&2; exit 1; }
echo "ok: SIGTERM after the run ends FreeFem++ at once (exit $rc)"
echo "PASS"
