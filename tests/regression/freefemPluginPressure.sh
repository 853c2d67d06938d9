#!/usr/bin/env bash
# The FreeFEM plug-in passes the rock's pore-pressure change from the script (issue "fluid
# pressure"): frictionSolve(".", pressure = P, pressureTimes = T) to a porePressure effect that
# says `data script;`. cases/paperBenchmarkFreeFem (n = 10; its horizontal fracture runs across
# the square and parts regions 1 and 2) with α_B = 0.8, p_b0 = 0.01 Pa, steps at t = 0.5
# (between the listed times 0.25 and 1), 1 (a listed time) and 1.5 (beyond: constant). Each
# run from the script must give the fracture tables of the command line with the equivalent
# case, every column to 1e-12 of its largest value (the residual column: of the largest τ).
# The two runs assemble the same load in another order (α_B Δp_b per cell, or Δp_b times the
# load of α_B), so they agree to round-off, not to the bit; the optimizer converges to
# round-off (|D|/|Σ| about 1e-15) and the problem is well conditioned (measured: below 1e-13).
# A pressure the run ignored, or took with another sign or at another time, changes p and the
# slip at the 10 % level.
#  1. a uniform field given per vertex of the unsplit mesh Th = `change` everywhere;
#  2. a field per region given per vertex of the split mesh Ths (the interface's nodes are
#     split, so each side's copy carries its own region's value) = `regions`; at the unsplit
#     mesh's numbering this field cannot be given;
#  3. a linear field on Th = `data` with a row at each cell's centroid (the mean of a linear
#     function over a triangle's vertices is its value at the centroid);
#  4. 3D: cases/strikeSlipFault on a coarse mesh3 (P1, two steps), a uniform field per vertex of
#     the split mesh = `change`;
#  5. bad calls end in a FreeFEM error with a message naming the argument and what was
#     expected, and leave the case folder as it was; frictionSolver on a case that says
#     `data script;` is refused naming the key.
# Usage: freefemPluginPressure.sh BIN_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
bin=$(cd "$1" && pwd) src=$(cd "$2" && pwd) work=$3
rm -rf "$work" && mkdir -p "$work"
[[ -f $bin/friction.so ]] || { echo "FAIL: $bin/friction.so is missing" >&2; exit 1; }
export FF_LOADPATH="$bin;/usr/lib/freefem++;./"
export FF_INCLUDEPATH=/usr/include/freefem++/idp
header='FoamFile { version 2.0; format ascii; class dictionary; object effects; }'

fresh() {  # fresh NAME CASE: a clean copy of cases/CASE, tables at full precision
  cp -r "$src/cases/$2" "$work/$1"
  (cd "$work/$1" && ./Allclean >/dev/null)
  sed -i 's/^writePrecision .*/writePrecision  17;/' "$work/$1/system/controlDict"
}
square() {  # square NAME EFFECT: paperBenchmarkFreeFem with the steps and the effect
  fresh "$1" paperBenchmarkFreeFem
  sed -i 's/^endTime .*/endTime         1.5;/; s/^deltaT .*/deltaT          0.5;/' \
    "$work/$1/system/controlDict"
  printf '%s\nrock { type porePressure; biotCoefficient 0.8; initial 0.01; %s }\n' "$header" \
    "$2" >"$work/$1/constant/effects"
}
freefem() {  # freefem DIR SCRIPT [ARGS]: FreeFem++ on DIR/SCRIPT, its log in DIR/log.FreeFem++
  local d=$1 s=$2
  shift 2
  (cd "$d" && FreeFem++ -nw -ns "$s" "$@" >log.FreeFem++ 2>&1) || {
    echo "FAIL: ${d##*/}: FreeFem++ failed:" >&2
    tail -n 20 "$d/log.FreeFem++" >&2
    exit 1
  }
  grep -q "^frictionSolve: exit status 0$" "$d/log.FreeFem++" || {
    echo "FAIL: ${d##*/}: frictionSolve did not return 0:" >&2
    tail -n 20 "$d/log.FreeFem++" >&2
    exit 1
  }
}
cli() {  # cli FROM TO EFFECT: FROM's folder (mesh file included) run by the command line with
  # its porePressure's `data script;` replaced by EFFECT
  cp -r "$1" "$2"
  rm -rf "$2"/[0-9].* "$2"/[1-9]* "$2/VTK" "$2/postProcessing" "$2/constant/splitMesh" "$2"/log.*
  sed -i "s|data script;|$3|" "$2/constant/effects"
  "$bin/splitFractureNodes" -case "$2" >"$2/log.splitFractureNodes" 2>&1
  "$bin/frictionSolver" -case "$2" >"$2/log.frictionSolver" 2>&1 || {
    echo "FAIL: ${2##*/}: frictionSolver failed:" >&2
    tail -n 20 "$2/log.frictionSolver" >&2
    exit 1
  }
}
same() {  # same SCRIPT_DIR CLI_DIR FRACTURE P_LOW P_HIGH TIME...: the tables agree, and at
  # the last time the fracture's pressure p lies in [P_LOW, P_HIGH] (takes the given field)
  /usr/bin/python3 - "$@" <<'EOF'
import sys
import numpy as np
a, b, fracture, low, high = sys.argv[1:6]
low, high = float(low), float(high)
times = sys.argv[6:]
header = open("%s/%s/fractures/%s.dat" % (b, times[0], fracture)).readline().split()[1:]
worst = 0
for t in times:
    x = np.genfromtxt("%s/%s/fractures/%s.dat" % (a, t, fracture), comments="#", dtype=str)
    y = np.genfromtxt("%s/%s/fractures/%s.dat" % (b, t, fracture), comments="#", dtype=str)
    assert x.shape == y.shape and x.shape[0] > 2, "t = %s: tables of %s and %s rows" % (
        t, x.shape, y.shape)
    assert (x[:, -1] == y[:, -1]).all(), "t = %s: the states differ" % t
    x, y = x[:, :-1].astype(float), y[:, :-1].astype(float)
    tau = np.nanmax(np.abs(y[:, header.index("tau" if "tau" in header else "tauMagnitude")]))
    for j, name in enumerate(header[:-1]):
        assert np.array_equal(np.isnan(x[:, j]), np.isnan(y[:, j])), "%s at t = %s" % (name, t)
        m = ~np.isnan(y[:, j])
        scale = tau if name == "residual" else np.max(np.abs(y[m, j]))
        d = np.max(np.abs(x[m, j] - y[m, j])) / max(scale, 1e-300)
        worst = max(worst, d)
        assert d <= 1e-12, "column %s at t = %s differs by %.2e of its largest" % (name, t, d)
p = x[:, header.index("pressure")]
assert np.nanmin(p) >= low - 1e-12 * high and np.nanmax(p) <= high + 1e-12 * high, \
    "p at t = %s from %s to %s, expected in [%s, %s]" % (times[-1], min(p), max(p), low, high)
print("ok: %s: tables at t = %s equal the command line's to %.1e of each column's largest"
      % (a.split("/")[-1], ", ".join(times), worst))
EOF
}

# 1.-3. The square, one script: the field is chosen by -field.
cat >"$work/pressure.edp" <<'EOF'
load "friction"
include "getARGV.idp"
string field = getARGV("-field", "uniform");
int n = 10;
include "square.idp"
mesh Ths = frictionSplit(Th, ".", overwrite = true);
real[int] T = [0.25, 1];
real[int, int] P(1, 2);
if (field == "uniform") {                  // per vertex of Th: 0, then 0.02 Pa
    P.resize(Th.nv, 2);
    for (int i = 0; i < Th.nv; ++i) { P(i, 0) = 0; P(i, 1) = 0.02; }
} else if (field == "regions") {           // per vertex of Ths: region 1 0.03, region 2 0.01
    P.resize(Ths.nv, 2);
    P = 0;
    for (int k = 0; k < Ths.nt; ++k)
        for (int j = 0; j < 3; ++j) P(Ths[k][j], 1) = Ths[k].label == 1 ? 0.03 : 0.01;
} else {                                    // linear, per vertex of Th; the same at centroids
    func real p(real x, real y) { return 0.01 + 0.02 * x - 0.015 * y; }
    P.resize(Th.nv, 2);
    for (int i = 0; i < Th.nv; ++i) { P(i, 0) = 0; P(i, 1) = p(Th(i).x, Th(i).y); }
    ofstream f("../centroids.dat");
    f.precision(17);
    for (int k = 0; k < Th.nt; ++k) {
        real x = (Th[k][0].x + Th[k][1].x + Th[k][2].x) / 3;
        real y = (Th[k][0].y + Th[k][1].y + Th[k][2].y) / 3;
        f << "0.25 " << x << " " << y << " 0" << endl << "1 " << x << " " << y << " " << p(x, y) << endl;
    }
}
int status = frictionSolve(".", overwrite = true, pressure = P, pressureTimes = T);
cout << "frictionSolve: exit status " << status << endl;
EOF
for field in uniform regions linear; do
  square "$field" "data script;"
  cp "$work/pressure.edp" "$work/$field/"
  freefem "$work/$field" pressure.edp -field "$field"
  grep -q "data from frictionSolve's pressure at 2 times" "$work/$field/log.FreeFem++" ||
    { echo "FAIL: $field: the log does not name the script's pressure" >&2; exit 1; }
done
cli "$work/uniform" "$work/uniformCli" "change table ((0.25 0) (1 0.02));"
same "$work/uniform" "$work/uniformCli" fracture 0.03 0.03 0.5 1 1.5
cli "$work/regions" "$work/regionsCli" \
  "regions { region1 { change table ((0.25 0) (1 0.03)); } region2 { change table ((0.25 0) (1 0.01)); } }"
# (p on the fracture: p_b0 + the mean of the two sides', between 0.02 and 0.04)
same "$work/regions" "$work/regionsCli" fracture 0.0201 0.0399 0.5 1 1.5
# (data rows sorted by time: the script wrote both times per centroid)
sort -s -k1,1g "$work/centroids.dat" >"$work/linear/constant/pb.dat"
cli "$work/linear" "$work/linearCli" 'data \"constant/pb.dat\";'
# (p on the fracture, y = 0.5 ± a cell: p_b0 + 0.01 + 0.02 x − 0.015 y within 0.0125 ... 0.0325)
same "$work/linear" "$work/linearCli" fracture 0.0125 0.0325 0.5 1 1.5

# 4. 3D: cases/strikeSlipFault's block, P1, steps 1 and 2; Δp_b 0 at t = 0, 5 MPa at t = 2.
d=$work/fault3d
fresh fault3d strikeSlipFault
sed -i 's/^endTime .*/endTime         2;/' "$d/system/controlDict"
printf '\nrock { type porePressure; biotCoefficient 1; initial 0; data script; }\n' \
  >>"$d/constant/effects"
sed -n '/^savemesh(Th, out);/q;p' "$d/constant/mesh/block.edp" >"$d/pressure3d.edp"
cat >>"$d/pressure3d.edp" <<'EOF'
load "friction"
mesh3 Ths = frictionSplit(Th, ".", overwrite = true);
real[int] T = [0, 2];
real[int, int] P(Ths.nv, 2);
for (int i = 0; i < Ths.nv; ++i) { P(i, 0) = 0; P(i, 1) = 5e6; }
int status = frictionSolve(".", overwrite = true, pressure = P, pressureTimes = T);
cout << "frictionSolve: exit status " << status << endl;
EOF
freefem "$d" pressure3d.edp -nFault 6 -nSide 6 -nLayers 3
cli "$d" "$work/fault3dCli" "change table ((0 0) (2 5e6));"
same "$d" "$work/fault3dCli" fault 5e6 5e6 1 2

# 5. Bad calls: a copy of the square whose porePressure says data script (split beforehand),
# SCRIPT after the mesh Th is made; FreeFEM must end with an error (not a signal) carrying
# EXPECTED, and the folder must stay as it was.
failures=0
bad() {  # bad NAME EXPECTED EFFECT SCRIPT
  local name=$1 expected=$2 d=$work/bad-$1 rc=0
  square "bad-$name" "$3"
  { echo 'load "friction"'; echo 'int n = 10;'; echo 'include "square.idp"';
    echo 'mesh Ths = frictionSplit(Th, ".");'; } >"$d/split.edp"
  (cd "$d" && FreeFem++ -nw -ns -v 0 split.edp >log.split 2>&1)
  local before after why=""
  before=$(cd "$d" && find . -type f | sort | xargs md5sum)
  { echo 'load "friction"'; echo 'int n = 10;'; echo 'include "square.idp"'; echo "$4"; } \
    >"$d/bad.edp"
  (cd "$d" && FreeFem++ -nw -ns -v 0 bad.edp >log.bad 2>&1) || rc=$?
  after=$(cd "$d" && find . -type f ! -name bad.edp ! -name log.bad | sort | xargs md5sum)
  if ((rc == 0 || rc >= 128)); then
    why="exit code $rc (expected a FreeFEM error: non-zero, not a signal)"
  elif grep -qiE "segmentation|abort|core dumped|terminate called" "$d/log.bad"; then
    why="the log shows a crash"
  elif ! grep -q "Exec error" "$d/log.bad"; then
    why="no FreeFEM 'Exec error' in the log"
  elif ! grep -qF -- "$expected" "$d/log.bad"; then
    why="the message lacks: $expected"
  elif [[ $before != "$after" ]]; then
    why="the case folder changed: $(diff <(echo "$before") <(echo "$after") | head -5 || true)"
  fi
  if [[ -n $why ]]; then
    echo "FAIL: $name: $why; the log ends:" >&2
    tail -n 8 "$d/log.bad" >&2
    failures=$((failures + 1))
  else
    echo "ok: $name: exit $rc, \"$(grep -m1 -o "frictionSolve: error: .*" "$d/log.bad" | cut -c1-150)\""
  fi
}
call='real[int] T = [0, 1];
real[int, int] P(Th.nv, 2);
P = 0;'
bad rows "frictionSolve: error: pressure: expected one row per vertex of the split mesh (144) or of the unsplit mesh (133), got 134 rows" \
  "data script;" "$call
P.resize(Th.nv + 1, 2);
int s = frictionSolve(\".\", pressure = P, pressureTimes = T);"
bad columns "frictionSolve: error: pressure: expected one column per time of pressureTimes (2), got 3 columns" \
  "data script;" "$call
P.resize(Th.nv, 3);
int s = frictionSolve(\".\", pressure = P, pressureTimes = T);"
bad times "frictionSolve: error: pressureTimes: entry 1 (0) does not follow entry 0 (0); expected times [s] strictly increasing" \
  "data script;" "$call
T[1] = 0;
int s = frictionSolve(\".\", pressure = P, pressureTimes = T);"
bad nonFinite "frictionSolve: error: pressure: row 7, column 1 is inf; expected finite values" \
  "data script;" "$call
P(7, 1) = 1e308 * 10;
int s = frictionSolve(\".\", pressure = P, pressureTimes = T);"
bad noTimes "frictionSolve: error: pressure: given without pressureTimes; expected both" \
  "data script;" "$call
int s = frictionSolve(\".\", pressure = P);"
bad noEffect "no active effect of the case takes it: add to constant/effects a porePressure entry that takes it, e.g. rock { type porePressure; biotCoefficient 1; initial 0; data script; }" \
  "change 0.01;" "$call
int s = frictionSolve(\".\", pressure = P, pressureTimes = T);"
# frictionSolver on a case whose pressure comes from the script: refused naming the key.
d=$work/bad-noEffect
sed -i 's/change 0.01;/data script;/' "$d/constant/effects"
before=$(cd "$d" && find . -type f | sort | xargs md5sum)
rc=0
"$bin/frictionSolver" -case "$d" >"$d/log.cli" 2>&1 || rc=$?
after=$(cd "$d" && find . -type f ! -name log.cli | sort | xargs md5sum)
if ((rc != 1)) || ! grep -qF "constant/effects:2: key 'data': 'script' says the program running the case gives the rock's pore-pressure change, and this run was given none" "$d/log.cli" ||
  [[ $before != "$after" ]]; then
  echo "FAIL: frictionSolver on a data script case: exit $rc; the log ends:" >&2
  tail -n 4 "$d/log.cli" >&2
  failures=$((failures + 1))
else
  echo "ok: frictionSolver: exit 1, \"$(grep -m1 -o "constant/effects.*" "$d/log.cli" | cut -c1-150)\""
fi
((failures == 0)) || { echo "$failures bad call(s) failed" >&2; exit 1; }
echo "PASS"
