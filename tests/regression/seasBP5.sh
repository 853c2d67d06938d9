#!/usr/bin/env bash
# faultOutput in 3D on cases/seasBP5 (SEAS BP5-QD) at fault cells of 10 km (the benchmark asks
# for 1 km; README "Benchmark: SEAS BP5-QD"), for 1e5 s: the nucleation zone (V_init = 0.01
# m/s) starts an earthquake within minutes. Checks what the specification and the format
# require, not earlier output:
#  * the station files: SEAS BP5's column line, eight numbers per row in the formats %21.13E
#    and %14.6E, strictly increasing times to the end time;
#  * the first rows, the specification's initial state: slip 0 0; log10 V_2 = -9 at the
#    centre (strk+00dp+10) and -2 in the nucleation zone (strk-24dp+10); V_3 = 0 exactly
#    (the prestress is along strike: -300, the floor); shear_stress_2 = tau0 = 19.490041 MPa
#    (a = 0.004, V_p) and 21.148085 MPa (nucleation, V_i = 0.01 m/s: 25 MPa a asinh(V_i/2V_0
#    e^(psi0/a)) + eta V_i), 13.273062 MPa at the surface (a = 0.04);
#    shear_stress_3 = 0; state log10(L/V_p) = 8.146128 (L = 0.14 m) and 8.113943 (0.13 m)
#    (to the 7 digits written);
#  * signs: the event drives the + side (y > 0) along +x: slip_2 > 0.1 m at strk-24dp+10 at
#    the end, and the station's rates and shears of one sign (V along the shear);
#  * global.dat: the stations' times; at t = 0 log10 max V = -2 and the moment rate
#    G sum A_i |V_i| within 1 % of G (0.01 x 12 km x 12 km + V_p x the rest) (the lumped
#    areas of the nucleation zone's nodes approximate its area: checked against the mesh);
#  * a run stopped at 5e4 s and restarted writes the very bytes of the uninterrupted one;
#  * law rateState's creepSlipRate: every node beyond the 100 km x 40 km has slipped V_p t
#    along +x exactly;
#  * refusals, exit 1 naming the key, nothing written: a station 30 km off the fault,
#    stations without strike, strike down the dip, profiles, surfaceStations and positiveSlip
#    in 3D, an arclength station in 3D, a creepDirection normal to the fault.
# Usage: seasBP5.sh BIN_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
bin=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work/full"
cp -r "$src/cases/seasBP5" "$work/full/bp5"
cd "$work/full/bp5"
./Allclean >/dev/null
/usr/bin/python3 bp5Case.py --years 1 >/dev/null
./Allmesh -h 10000 >/dev/null
"$bin/splitFractureNodes" -case . >log.splitFractureNodes 2>&1
sed -i 's/^endTime .*/endTime 1e5;/; s/^deltaT .*/deltaT 5e4;/; s/^writeInterval .*/writeInterval 1;/' system/controlDict
mkdir -p "$work/restarted"
cp -r . "$work/restarted/bp5"
"$bin/frictionSolver" -case . >log.frictionSolver 2>&1
out=postProcessing/faultOutput
[[ $(ls $out/fltst_*.dat | wc -l) == 10 ]] || { echo "FAIL: 10 station files expected"; ls $out; exit 1; }
/usr/bin/python3 - "$out" <<'PY'
import glob, math, re, sys
out = sys.argv[1]
columns = "t slip_2 slip_3 slip_rate_2 slip_rate_3 shear_stress_2 shear_stress_3 state"
row = re.compile(r"^ +-?\d\.\d{13}E[+-]\d\d( +-?\d\.\d{6}E[+-]\d\d){7}$")
first = {}
for path in sorted(glob.glob(out + "/fltst_*.dat")):
    lines = open(path).read().splitlines()
    head = [l for l in lines if l.startswith("#")]
    assert len(head) == 10 and lines[10] == columns, (path, lines[:12])
    data = lines[11:]
    assert len(data) >= 100, (path, len(data))
    for l in data:
        assert row.match(l) and len(l) == 21 + 7 * 15, (path, l)  # %21.13E, then " %14.6E"
    t = [float(l.split()[0]) for l in data]
    assert all(b > a for a, b in zip(t, t[1:])) and t[0] == 0 and abs(t[-1] - 1e5) < 1e-6, path
    first[path.split("fltst_")[1][:-4]] = [float(v) for v in data[0].split()]
    last = [float(v) for v in data[-1].split()]
    # V along the shear: rate and shear of one sign on each direction where both are resolved.
    if path.endswith("strk-24dp+10.dat"):
        assert last[1] > 0.1, ("the event's slip at strk-24dp+10", last)
# The specification's initial state: theta0 = L/V_p, and tau0 such that V = V_init under it.
psi0 = 0.6 + 0.03 * math.log(1e-6 / 1e-9)
eta = 2670 * 3464.0 / 2
tau0 = lambda a, V: (25e6 * a * math.asinh(V / 2e-6 * math.exp(psi0 / a)) + eta * V) / 1e6
expect = {  # slip_2 slip_3 log V_2 log V_3 tau_2 tau_3 log theta
    "strk+00dp+10": (0, 0, -9, -300, tau0(0.004, 1e-9), 0, math.log10(0.14 / 1e-9)),
    "strk-24dp+10": (0, 0, -2, -300, tau0(0.004, 0.01), 0, math.log10(0.13 / 1e-9)),
    "strk+00dp+00": (0, 0, -9, -300, tau0(0.04, 1e-9), 0, math.log10(0.14 / 1e-9)),
}
assert abs(tau0(0.004, 1e-9) - 19.490041) < 1e-6  # the value tandem and Thrase start from
for name, e in expect.items():
    got = first[name][1:]
    for g, x, what in zip(got, e, columns.split()[1:]):
        tol = 1.5e-6 * max(1.0, abs(x))  # the 7 digits written
        assert abs(g - x) <= tol, (name, what, g, x)
print("PASS: 10 station files in SEAS BP5's format; first rows the specification's initial state")
g = open(out + "/global.dat").read().splitlines()
assert g[4] == "t max_slip_rate moment_rate", g[:5]
g0 = [float(v) for v in g[5].split()]
G = 2670 * 3464.0 ** 2
nuc = 12e3 * 12e3
# The whole plane y = 0 is the fault (400 km x 100 km); nodes on the nucleation zone's border
# carry V_init = 0.01 over about half their lumped area at 10 km cells: the bound below holds
# the sum between the zone's area and the area of its cells' closure.
low, high = G * (0.01 * nuc), G * (0.01 * (12e3 + 10e3) ** 2 + 1e-9 * 4e10)
assert g0[0] == 0 and abs(g0[1] + 2) < 1e-6 and low * 0.99 <= g0[2] <= high, g0
ts = [float(l.split()[0]) for l in g[5:]]
st = [float(l.split()[0]) for l in open(out + "/fltst_strk+00dp+10.dat").read().splitlines()[11:]]
assert ts == st, "global.dat at the stations' times"
print("PASS: global.dat at the stations' times, log10 max V = -2 and the moment rate at t = 0")
PY
# creepSlipRate: beyond the 100 km x 40 km every node has slipped V_p t along +x exactly (Omega+
# is y > 0), those on it not by that; but those on the sides, which their Dirichlet conditions
# hold.
/usr/bin/python3 - <<'PY'
lines = open("100000/fractures/fault.dat").read().splitlines()
h = lines[0][1:].split()
rows = [[float(v) for v in l.split()[:-1]] for l in lines if not l.startswith("#")]
ix, iz, isx, isy, isz = (h.index(c) for c in ("x", "z", "slipX", "slipY", "slipZ"))
# (Nodes on the sides x = -/+200 km are held by the sides' Dirichlet conditions.)
outside = [r for r in rows if (abs(r[ix]) > 50001 or r[iz] < -40001) and abs(r[ix]) < 199999]
inside = [r for r in rows if abs(r[ix]) < 49999 and r[iz] > -39999]
assert len(outside) >= 50 and len(inside) >= 20, (len(outside), len(inside))
worst = max(abs(r[isx] - 1e-9 * 1e5) + abs(r[isy]) + abs(r[isz]) for r in outside)
assert worst <= 1e-9 * 1e-4, worst  # round-off of V t
assert any(abs(r[isx] - 1e-4) > 1e-6 for r in inside)
print(f"PASS: {len(outside)} nodes beyond the rate-and-state rectangle crept V_p t along +x "
      f"(to {worst:.1e} m)")
PY
grep -q "^Fracture fault: [0-9]* of [0-9]* nodes creep (creepSlipRate > 0) along (1 0 0)" log.frictionSolver
# Restart, byte for byte.
cd "$work/restarted/bp5"
sed -i 's/^endTime .*/endTime 5e4;/' system/controlDict
"$bin/frictionSolver" -case . >log.1 2>&1
sed -i 's/^endTime .*/endTime 1e5;/; s/^startTime .*/startTime 0;\nstartFrom latestTime;/' system/controlDict
"$bin/frictionSolver" -case . >log.2 2>&1
grep -q "^Restarting from time 50000 (step 1)" log.2 || { echo "FAIL: not restarted at 5e4 s"; exit 1; }
n=0
for f in "$work"/full/bp5/postProcessing/faultOutput/*.dat "$work"/full/bp5/[1-9]*/uniform/frictionState; do
  cmp -s "$f" "${f/full/restarted}" || { echo "FAIL: restarted ${f#$work/full/} differs"; exit 1; }
  n=$((n + 1))
done
((n == 13)) || { echo "FAIL: $n files compared, 13 expected"; exit 1; }
echo "PASS: stopped at 5e4 s and restarted: $n files byte for byte as the uninterrupted run's"

# Refusals: exit 1, the key named, no output folder.
refuse() {  # NAME SED-SCRIPT MESSAGE
  rm -rf "$work/$1"
  cp -r "$work/full/bp5" "$work/$1"
  cd "$work/$1"
  rm -rf postProcessing [1-9]* VTK log.frictionSolver
  sed -i "$2" system/controlDict
  local rc=0
  "$bin/frictionSolver" -case . >log 2>&1 || rc=$?
  [[ $rc == 1 ]] && grep -q -- "$3" log && [[ ! -e postProcessing/faultOutput ]] ||
    { echo "FAIL: $1 (exit $rc)"; cat log; exit 1; }
}
refuse offFault 's/fltst_strk+00dp+22 (0 0 -22000);/fltst_strk+00dp+22 (0 30000 -22000);/' \
  "controlDict:.*station 'fltst_strk+00dp+22' at (0 30000 -22000): not on fracture 'fault': its nearest node, at (0 0 -20000), is 30066.59276 m away, farther than a cell (10000 m"
refuse noStrike '/^    strike /d' "controlDict:.*faultOutput: 3D stations need 'strike (x y z)'"
refuse alongDip 's/^    strike .*/    strike (0 0 1);/' "controlDict:.*faultOutput: strike (0 0 1) runs down the fault's dip"
refuse profiles 's/^    seismicSlipRate.*/&\n    profiles { from 0; to 40000; spacing 500; interval 1; }/' \
  "controlDict:.*faultOutput: 'profiles' run along a 2D fracture's arclength"
refuse surface 's/^    seismicSlipRate.*/&\n    surfaceStations { srf (0 1000 0); }/' \
  "controlDict:.*faultOutput: 'surfaceStations' are written for 2D cases only so far"
refuse positive 's/^    seismicSlipRate.*/&\n    positiveSlip (1 0 0);/' \
  "controlDict:.*faultOutput: 'positiveSlip' is the 2D key; in 3D give 'strike (x y z)'"
refuse arclength 's/fltst_strk+00dp+22 (0 0 -22000);/fltst_strk+00dp+22 22000;/' \
  "controlDict:.*station 'fltst_strk+00dp+22': in 3D a station is a point (x y z)"
# A creep direction normal to the fault.
rm -rf "$work/creepNormal" && cp -r "$work/full/bp5" "$work/creepNormal" && cd "$work/creepNormal"
rm -rf postProcessing [1-9]* VTK
sed -i 's/^    creepDirection .*/    creepDirection      (0 1 0);/' constant/fractureProperties
rc=0
"$bin/frictionSolver" -case . >log 2>&1 || rc=$?
[[ $rc == 1 ]] && grep -q "constant/fractureProperties: fracture 'fault': creepDirection is normal to the fracture at the node at" log ||
  { echo "FAIL: creepDirection normal to the fault (exit $rc)"; cat log; exit 1; }
echo "PASS: 3D refusals (off the fault, no strike, strike down the dip, profiles, surface stations, positiveSlip, an arclength, creepDirection normal to the fault)"
