#!/usr/bin/env bash
# Bad calls of the FreeFEM plug-in from a script (issue 15): each must end FreeFem++ with a
# FreeFEM error (an exit code, no crash: not a signal) carrying the command-line tools'
# message, and leave the case folder as it was (no split mesh, no time folder, no mesh file
# that was not there).
# Usage: freefemPluginErrors.sh BIN_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
bin=$(cd "$1" && pwd) src=$(cd "$2" && pwd) work=$3
rm -rf "$work" && mkdir -p "$work"
[[ -f $bin/friction.so ]] || { echo "FAIL: $bin/friction.so is missing" >&2; exit 1; }
export FF_LOADPATH="$bin;/usr/lib/freefem++;./"
export FF_INCLUDEPATH=/usr/include/freefem++/idp
failures=0

# scenario NAME EXPECTED EDIT SCRIPT: a clean copy of cases/paperBenchmarkFreeFem, EDIT run in
# it (a shell command), then SCRIPT (FreeFEM code after the case's mesh, Th, is made).
scenario() {
  local name=$1 expected=$2 edit=$3 script=$4 d=$work/$1 rc=0
  cp -r "$src/cases/paperBenchmarkFreeFem" "$d"
  (cd "$d" && ./Allclean >/dev/null && eval "$edit")
  local before
  before=$(cd "$d" && find . -type f | sort | xargs md5sum)
  { echo 'load "friction"'; echo 'int n = 10;'; echo 'include "square.idp"'; echo "$script"; } \
    >"$d/bad.edp"
  (cd "$d" && FreeFem++ -nw -ns -v 0 bad.edp >log.bad 2>&1) || rc=$?
  local after
  after=$(cd "$d" && find . -type f ! -name bad.edp ! -name log.bad | sort | xargs md5sum)
  local why=""
  if ((rc == 0 || rc >= 128)); then
    why="exit code $rc (expected a FreeFEM error: non-zero, not a signal)"
  elif grep -qiE "segmentation|abort|core dumped|terminate called" "$d/log.bad"; then
    why="the log shows a crash"
  elif ! grep -q "Exec error" "$d/log.bad"; then
    why="no FreeFEM 'Exec error' in the log"
  elif ! grep -qF -- "$expected" "$d/log.bad"; then
    why="the message lacks: $expected"
  elif grep -q "error: Exec error" "$d/log.bad"; then
    why="the message is wrapped twice (a FreeFEM error caught and reported again)"
  elif [[ $before != "$after" ]]; then
    why="the case folder changed: $(diff <(echo "$before") <(echo "$after") | head -5 || true)"
  fi
  if [[ -n $why ]]; then
    echo "FAIL: $name: $why; the log ends:" >&2
    tail -n 8 "$d/log.bad" >&2
    failures=$((failures + 1))
  else
    echo "ok: $name: exit $rc, \"$(grep -m1 -o "fricti[a-zA-Z]*: error: .*" "$d/log.bad" | cut -c1-110)\""
  fi
}

# An unknown friction law in constant/fractureProperties: frictionSolve names the file, the
# line and the laws, and writes no time folder. (The case is split beforehand, by the
# command line, so that the check of the folder is the solve's.)
scenario unknownLaw "constant/fractureProperties:12: key 'law': unknown value 'coulom'; did you mean 'coulomb'?" \
  "sed -i 's/law                 coulomb;/law                 coulom;/' constant/fractureProperties &&
   mkdir -p constant/mesh && cp \"\$src/cases/paperBenchmark/constant/mesh/square.msh\" constant/mesh/ &&
   \"\$bin/splitFractureNodes\" -case . >/dev/null" \
  'int s = frictionSolve(".");'
# A label that is not a fracture: the mesh's fracture carries label 7, meshDict says 5. The
# mesh file frictionSplit wrote is taken back.
scenario labelNotAFracture "patch 'fracture': label 5 does not occur among the edges" \
  "true" \
  'int[int] relabel = [5, 7];
Th = change(Th, label = relabel);
mesh Ths = frictionSplit(Th, ".");'
# A fracture the case does not have, asked for the table (the case split beforehand).
scenario unknownFracture "fracture = \"fracure\": not a fracture of the case; expected one of fracture; did you mean 'fracture'?" \
  "mkdir -p constant/mesh && cp \"\$src/cases/paperBenchmark/constant/mesh/square.msh\" constant/mesh/ &&
   \"\$bin/splitFractureNodes\" -case . >/dev/null" \
  'real[int, int] T(1, 1);
int s = frictionSolve(".", table = T, fracture = "fracure");'
# The displacement into a P2 space for a P1 case (the case split beforehand).
scenario wrongOrder "Vh: expected a P1 fespace on the mesh frictionSplit returned" \
  "mkdir -p constant/mesh && cp \"\$src/cases/paperBenchmark/constant/mesh/square.msh\" constant/mesh/ &&
   \"\$bin/splitFractureNodes\" -case . >/dev/null" \
  'fespace Vh(Th, P2);
Vh ux, uy;
int s = frictionSolve(".", Vh, ux[], uy[]);'
# A case folder that does not exist.
scenario noCase "nowhere: the case folder does not exist" \
  "true" \
  'mesh Ths = frictionSplit(Th, "nowhere");'
# Another mesh in the file meshDict names, without overwrite = true.
scenario otherMesh "holds another mesh than the one given to frictionSplit" \
  "mkdir -p constant/mesh && cp \"\$src/cases/paperBenchmark/constant/mesh/square.msh\" constant/mesh/" \
  'mesh Ths = frictionSplit(Th, ".");'

# A second run over the time folders of a first, without overwrite = true: refused, and the
# message names the plug-in's way to start again, not the command line's.
scenario secondSolve 'frictionSolve(".", overwrite = true)' \
  "mkdir -p constant/mesh && cp \"\$src/cases/paperBenchmark/constant/mesh/square.msh\" constant/mesh/ &&
   \"\$bin/splitFractureNodes\" -case . >/dev/null && \"\$bin/frictionSolver\" -case . >/dev/null" \
  'int s = frictionSolve(".");'
if grep -q "frictionSolver -overwrite" "$work/secondSolve/log.bad"; then
  echo "FAIL: secondSolve: the message tells a script user to run frictionSolver -overwrite" >&2
  failures=$((failures + 1))
fi
# A case locked by a living run (here a sleeping process named in the lock file): frictionSolve
# takes the lock as frictionSolver does, and is refused before anything is written.
sleep 300 >/dev/null 2>&1 &
holder=$!
trap 'kill $holder 2>/dev/null' EXIT
scenario locked "the case is in use: frictionSolver (process $holder on host" \
  "mkdir -p constant/mesh && cp \"\$src/cases/paperBenchmark/constant/mesh/square.msh\" constant/mesh/ &&
   \"\$bin/splitFractureNodes\" -case . >/dev/null && echo \"$holder \$(hostname) frictionSolver\" >.frictionSolver.lock" \
  'int s = frictionSolve(".", overwrite = true);'

((failures == 0)) || { echo "$failures scenario(s) failed" >&2; exit 1; }
echo "PASS"
