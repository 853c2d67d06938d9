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
#  5. a pressure front crossing a junction (cases/fractureNetwork).
# Usage: pressureStability.sh BIN_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
bin=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
cp -r "$src/cases/viescaInjection" "$work/base"
(cd "$work/base" && ./Allclean >/dev/null && ./Allmesh -h 0.2 >/dev/null)
fail() { echo "FAIL [pressureStability]: $*"; exit 1; }

# A copy of the base case with the given effects' fluid entry and controlDict time keys.
make() {  # make NAME FLUID_BODY TIME_KEYS [CONTACT]
  local d=$work/$1
  mkdir -p "$d"
  cp -r "$work/base/0" "$work/base/constant" "$work/base/system" "$d"/
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
            assert math.isfinite(x) or r["state"] == "tip", (name, k, v)
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
echo "PASS: pressure stability, 7 runs"
