#!/usr/bin/env bash
# Stability of fluid-driven cases (issue: fluid pressure), on cases/viescaInjection's set-up
# with a coarse fault mesh (h = 0.2 m): each run must end (under timeout) with exit 0, every
# step converged, no non-finite value in any table, and the answer's own physics:
#  1. a pressure above the confinement everywhere on the fault (p0 = 12 MPa against
#     sigma'_0 = 10 MPa): every node open (sigma'_n >= 0), tau = 0, and the log's note saying
#     so; with contact unilateral too (the faces then open);
#  2. a well at the fault's tip, the pressure computed by diffusion: it runs, slips next to
#     the tip and nowhere beyond the diffusion length;
#  3. steps from 1 ms to a year (deltaTGrowth, the pressure computed by diffusion with
#     Crank-Nicolson, a constant rate): every step converged, the part at its friction bound
#     (slip, then open) never shrinks;
#  4. an opening (unilateral) at the well while the neighbouring part slips: both states
#     present in one step;
#  5. a pressure front crossing a junction (cases/fractureNetwork);
#  6. a well on a Dirichlet patch: the fault reaches the held outer boundary (one end there,
#     or both: it crosses the body), 5 MPa held at (or one node from) that boundary, computed
#     by diffusion: the pressure within [0, 5 MPa] and falling away from the well, the jump
#     held at zero on the boundary, Coulomb elsewhere, slip of one sign near the well only and
#     never shrinking.
# Usage: pressureStability.sh BIN_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
bin=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
cp -r "$src/cases/viescaInjection" "$work/base"
(cd "$work/base" && ./Allclean >/dev/null && ./Allmesh -h 0.2 >/dev/null)
fail() { echo "FAIL [pressureStability]: $*"; exit 1; }

# A copy of the base case with the given effects' fluid entry and controlDict time keys.
make() {  # make NAME FLUID_BODY TIME_KEYS [CONTACT]   (BASE=folder: another base case)
  local d=$work/$1 b=${BASE:-$work/base}
  mkdir -p "$d"
  cp -r "$b/0" "$b/constant" "$b/system" "$d"/
  /usr/bin/python3 - "$d/constant/effects" "$2" <<'PY'
import sys, re
path, body = sys.argv[1], sys.argv[2]
s = open(path).read()
s = re.sub(r"fluid\s*\{.*\}\s*$", "fluid\n{\n" + body + "\n}\n", s, flags=re.S)
open(path, "w").write(s)
PY
  sed -i "/^endTime\|^deltaT\|^writeInterval\|^writeControl/d" "$d/system/controlDict"
  echo "$3" >>"$d/system/controlDict"
  if [[ ${4:-} == unilateral ]]; then
    sed -i 's/    frictionCoefficient 0.6;/    frictionCoefficient 0.6;\n    contact unilateral;/' \
      "$d/constant/fractureProperties"
  fi
  "$bin/splitFractureNodes" -case "$d" >"$d/log.splitFractureNodes" 2>&1 || fail "$1: split"
  timeout 300 "$bin/frictionSolver" -case "$d" >"$d/log.frictionSolver" 2>&1 ||
    fail "$1: exit $? ($(tail -n 3 "$d/log.frictionSolver" | tr '\n' ' '))"
  grep -q "^Time = .*converged" "$d/log.frictionSolver" || fail "$1: no converged step"
  if grep "^Time = " "$d/log.frictionSolver" | grep -vq " converged"; then
    fail "$1: a step did not converge: $(grep '^Time = ' "$d/log.frictionSolver" | grep -v ' converged' | head -n 1)"
  fi
}

# The states and values of the newest table of case $1: "state count" lines, and a check that
# every number is finite but the tips' tractions.
check() {  # check NAME PYTHON_ASSERTIONS
  /usr/bin/python3 - "$work/$1" "$2" <<'PY'
import math, os, sys
case, code = sys.argv[1], sys.argv[2]
times = sorted((float(d), d) for d in os.listdir(case)
               if d.replace(".", "", 1).replace("e-", "", 1).replace("e+", "", 1).isdigit()
               and float(d) > 0)
tables = []
for _, name in times:
    lines = open(os.path.join(case, name, "fractures", "fault.dat")).read().splitlines()
    header = lines[0][1:].split()
    rows = [dict(zip(header, l.split())) for l in lines if not l.startswith("#")]
    assert rows, name
    for r in rows:
        for k, v in r.items():
            if k == "state":
                continue
            x = float(v)
            assert math.isfinite(x), (name, k, v)  # tips too: the body's stress there
    tables.append((name, rows))
last = tables[-1][1]
states = lambda rows: {s: sum(r["state"] == s for r in rows) for s in ("stick", "slip", "open", "tip")}
exec(code)
print("PASS:", os.path.basename(case), states(last))
PY
}

# 1. Above the confinement everywhere, bilateral and unilateral.
for contact in bilateral unilateral; do
  make "above-$contact" "    type faultPressure; fracture fault; initial 12e6;" "times (1 2);" "$contact"
  grep -q "Note: every node of fracture fault is open" "$work/above-$contact/log.frictionSolver" ||
    fail "above-$contact: no note that every node is open"
  check "above-$contact" '
s = states(last)
assert s["open"] == len(last) - s["tip"] and s["slip"] == s["stick"] == 0, s
for r in last:
    if r["state"] == "open":
        assert float(r["sigmaNEffective"]) >= -1e-6 * 1e7 and abs(float(r["tau"])) <= 1e-6 * 1e7, r
'
done

# 2. A well at the tip (x = 15 m), computed diffusion.
make tipWell "    type faultPressure; fracture fault; initial 0;
    model diffusion; storage 1e-9; transmissivity 1e-9;
    wells { tip { position (15 0); pressure 5e6; } }" "times (0.25 0.5 1);"
check tipWell '
s = states(last)
assert s["slip"] > 0, s
xs = [float(r["x"]) for r in last if r["state"] == "slip"]
assert min(xs) > 15 - 2 * 3.64 * 2, xs  # within the rupture of a held pressure (lambda(0.1) sqrt(4 alpha t))
'

# 3. Steps from 1 ms to a year, Crank-Nicolson, a rate well.
make years "    type faultPressure; fracture fault; initial 0;
    model diffusion; storage 1e-9; transmissivity 1e-12; scheme crankNicolson;
    wells { well { position (0 0); rate 1e-7; } }" \
  "endTime 3.15e7; deltaT 1e-3; deltaTGrowth 2; writeControl timeStep; writeInterval 1;"
check years '
# The rising pressure first makes the fault slip around the well, then (above sigma_0 = 10 MPa
# at the well: a constant rate into a fault with no-flow ends) open: the part at its friction
# bound (slip or open) never shrinks, and both states occur.
assert len(tables) >= 30, len(tables)
failed = [sum(r["state"] in ("slip", "open") for r in rows) for _, rows in tables]
assert all(b >= a for a, b in zip(failed, failed[1:])), failed
assert failed[-1] > 0, failed
assert any(states(rows)["slip"] > 0 for _, rows in tables)
assert any(states(rows)["open"] > 0 for _, rows in tables)
'

# 4. Opening at the well while the neighbours slip (unilateral, 12 MPa held at the well).
make openAndSlip "    type faultPressure; fracture fault; initial 0; diffusivity 1;
    wells { injector { position (0 0); pressure 12e6; } }" "times (0.25 1);" unilateral
check openAndSlip '
s = states(last)
assert s["open"] > 0 and s["slip"] > 0, s
'
# 5. A pressure front that crosses a junction: cases/fractureNetwork (faultA and faultB cross
#    at (2000, -1700)) with 5 MPa held on faultB 200 m from the crossing, diffusing along both
#    faults: the junction has one pressure in both tables, and faultA takes the fluid on both
#    sides of the crossing.
d=$work/junctionFront
cp -r "$src/cases/fractureNetwork" "$d"
(cd "$d" && ./Allclean >/dev/null)
cat >>"$d/constant/effects" <<'DICT'
fluid
{
    type        faultPressure;
    fractures   (faultA faultB);
    initial     0;
    model       diffusion;
    storage     1e-9;
    transmissivity 1e-9;
    wells { w { position (1900 -1526.7949192431123); pressure 5e6; } }
}
DICT
sed -i "/^endTime\|^deltaT/d" "$d/system/controlDict"
echo "times (1000 10000 100000);" >>"$d/system/controlDict"
"$bin/splitFractureNodes" -case "$d" >"$d/log.splitFractureNodes" 2>&1 || fail "junctionFront: split"
timeout 300 "$bin/frictionSolver" -case "$d" >"$d/log.frictionSolver" 2>&1 || fail "junctionFront: exit $?"
[[ $(grep -c "^Time = .* converged" "$d/log.frictionSolver") == 3 ]] || fail "junctionFront: a step did not converge"
/usr/bin/python3 - "$d/100000/fractures" <<'PY'
import math, sys
at = {}
for f in ("faultA", "faultB"):
    lines = open(f"{sys.argv[1]}/{f}.dat").read().splitlines()
    h = lines[0][1:].split()
    rows = [dict(zip(h, l.split())) for l in lines if not l.startswith("#")]
    at[f] = [float(r["pressure"]) for r in rows
             if math.hypot(float(r["x"]) - 2000, float(r["y"]) + 1700) < 1e-6]
    assert at[f], f"no row of {f} at the junction"
    if f == "faultA":  # both sides of the crossing, within 100 m, take the fluid
        sides = [(float(r["x"]) - 2000, float(r["pressure"])) for r in rows
                 if 1 < math.hypot(float(r["x"]) - 2000, float(r["y"]) + 1700) < 100]
        assert any(x < 0 and p > 1e5 for x, p in sides) and any(x > 0 and p > 1e5 for x, p in sides), sides
values = at["faultA"] + at["faultB"]
assert max(values) - min(values) <= 1e-9 * max(values), values
print(f"PASS: junctionFront: one pressure at the junction ({values[0]:.6g} Pa in {len(values)} rows), faultA pressurised on both sides")
PY

# 6. A well on a Dirichlet patch. The base case's dictionaries on a square [-15, 15]^2 held on
#    every side (0/D), its right side (and left, for the crossing fault) cut at y = 0 where the
#    fault meets it, the fault from (xl, 0) to (15, 0) (xl = -10: a tip inside; xl = -15: it
#    crosses the body, which it cuts in two held halves), h = 0.2 m along it.
edgeMesh() {  # edgeMesh FOLDER XL
  mkdir -p "$1/constant/mesh"
  cp -r "$work/base/0" "$work/base/system" "$1"/
  cp "$work/base/constant/"*Properties "$work/base/constant/effects" "$1/constant/"
  cat >"$1/constant/mesh/edge.geo" <<'GEO'
DefineConstant[ W = 15, xl = -10, h = 0.2, hFar = 3 ];
General.NumThreads = 1;
Mesh.RandomSeed = 1;
Mesh.Algorithm = 6;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Point(1) = {-W, -W, 0}; Point(2) = {W, -W, 0}; Point(3) = {W, 0, 0};
Point(4) = {W, W, 0}; Point(5) = {-W, W, 0}; Point(6) = {-W, 0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6};
Line(6) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6}; Plane Surface(1) = {1};
If (xl > -W)
  Point(7) = {xl, 0, 0};
  Line(7) = {7, 3};
Else
  Line(7) = {6, 3};
EndIf
Transfinite Curve{7} = Round((W - xl)/h) + 1;
Curve{7} In Surface{1};
Field[1] = Distance;
Field[1].CurvesList = {7};
Field[1].NumPointsPerCurve = 4*Round((W - xl)/h) + 1;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hFar;
Field[2].DistMin = 4*h;
Field[2].DistMax = W/2;
Background Field = 2;
Physical Curve("bottom", 1) = {1};
Physical Curve("right", 2) = {2, 3};
Physical Curve("top", 3) = {4};
Physical Curve("left", 4) = {5, 6};
Physical Curve("fault", 5) = {7};
Physical Surface("body", 1) = {1};
GEO
  (cd "$1/constant/mesh" && gmsh -2 -format msh41 -setnumber xl "$2" edge.geo -o viesca.msh \
    >"$1/log.gmsh" 2>&1) || fail "gmsh: $(tail -n 3 "$1/log.gmsh")"
}
edgeMesh "$work/edgeTouch" -10
edgeMesh "$work/edgeCross" -15
# Per written time t (0.25, 0.5, 1 s): the pressure, from backward Euler with a lumped mass on
# a chain of segments (a discrete maximum principle), lies in [0, 5 MPa], is 5 MPa at the well
# and falls away from it; the nodes on the held sides (|x| = 15) keep a zero jump; every other
# inner node meets Coulomb (|tau| <= mu |sigma'_n|, equal where it slips) under compression
# (5 MPa < sigma'_0 = 10 MPa: nothing opens); the slipping nodes lie within the rupture of a
# held pressure (2 lambda(0.1) sqrt(4 alpha t), the bound of run 2), all slip one way (tau_0
# drives it) and no node's slip shrinks from one time to the next (the pressure only rises).
edgeChecks='
mu, dp = 0.6, 5e6
maxSlip = max(abs(float(r["slip"])) for _, rows in tables for r in rows)
assert maxSlip > 0, "no slip at all"
previous = None
for name, rows in tables:
    t = float(name)
    dist = [abs(float(r["x"]) - well[0]) for r in rows]
    p = [float(r["pressure"]) for r in rows]
    iw = min(range(len(rows)), key=lambda i: dist[i])
    assert dist[iw] < 1e-9 and abs(p[iw] - dp) <= 1e-9 * dp, (name, rows[iw])
    assert all(-1e-9 * dp <= v <= dp * (1 + 1e-12) for v in p), (name, min(p), max(p))
    order = sorted(range(len(rows)), key=lambda i: dist[i])
    assert all(p[b] <= p[a] + 1e-9 * dp for a, b in zip(order, order[1:])), (name, "p rises away from the well")
    held = [r for r in rows if abs(abs(float(r["x"])) - 15) < 1e-9]
    assert held and all(float(r["slip"]) == 0 and r["state"] == "stick" for r in held), (name, held)
    slipping = [r for r in rows if r["state"] == "slip"]
    assert len(slipping) >= 3, (name, states(rows))
    for r in rows:
        if r["state"] == "tip" or r in held:
            continue
        sn, tau = float(r["sigmaNEffective"]), abs(float(r["tau"]))
        assert sn < 0 and tau <= mu * -sn * (1 + 1e-6), (name, r)
        if r["state"] == "slip":
            assert abs(tau - mu * -sn) <= 1e-6 * mu * -sn, (name, r)
    reach = 2 * 3.6405 * (4 * 1.0 * t) ** 0.5
    assert all(abs(float(r["x"]) - well[0]) <= reach for r in slipping), (name, reach)
    signs = {float(r["slip"]) > 0 for r in rows if abs(float(r["slip"])) > 1e-9 * maxSlip}
    assert len(signs) == 1, (name, "slip of both signs")
    slip = {r["x"]: abs(float(r["slip"])) for r in rows}
    if previous:
        assert all(slip[x] >= previous[x] - 1e-9 * maxSlip for x in slip), (name, "slip shrank")
    previous = slip
'
for run in "atBoundary edgeTouch (15 0)" "nextToBoundary edgeCross (-14.8 0)"; do
  read -r name base well <<<"$run"
  BASE=$work/$base make "$name" "    type faultPressure; fracture fault; initial 0;
    model diffusion; storage 1e-9; transmissivity 1e-9;
    wells { edge { position $well; pressure 5e6; } }" "times (0.25 0.5 1);"
  grep -q "fracture node(s) lie on a Dirichlet patch: their jump is held at zero" \
    "$work/$name/log.frictionSolver" || fail "$name: no note of the fault's nodes on the held patch"
  check "$name" "well = tuple(float(v) for v in '$well'.strip('()').split())
$edgeChecks"
done
echo "PASS: pressure stability, 9 runs"
