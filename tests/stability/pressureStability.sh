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
#     present in one step.
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
echo "PASS: pressure stability, 6 runs"
