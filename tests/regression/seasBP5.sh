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
#    stations without strike, strike down the dip, profiles and positiveSlip in 3D, a surface
#    station given (x y) or above the free surface, an arclength station in 3D, a
#    creepDirection normal to the fault;
#  * ruptures (rupture_<k>.dat): the events are global.dat's (onset and end where its largest
#    slip rate crosses 1e-3 m/s), one row per moved node, the first event's ruptured nodes
#    at time 0 inside the nucleation zone (V_init = 0.01 m/s), the second's times within the
#    event and not all 0, its slip at the station strk-24dp+10 the station file's over the
#    event; stopped inside the second event and restarted, the same bytes; 'ruptures'
#    without strike refused;
#  * surface stations (3D): the format (seven columns), the faces y = +-100 km, held, at
#    exactly +-V_p t/2 and +-V_p/2 along x; 1 km either side of the trace above the
#    nucleation zone, the event's right-lateral motion (+x on the + side, -x on the -), and
#    at the end time the written volume solution interpolated there (VTK's cell search).
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
# Surface stations: on the faces y = +-100 km (held, moving +-V_p t/2 along x), and on the free
# surface 1 km either side of the fault above the nucleation zone.
sed -i 's/^    seismicSlipRate.*/&\n    surfaceStations { srf_plus (0 100000 -50000); srf_minus (0 -100000 -50000); srf_nucP (-24000 1000 0); srf_nucM (-24000 -1000 0); }/' system/controlDict
grep -q "srf_nucM" system/controlDict || { echo "FAIL: no surface stations set"; exit 1; }
mkdir -p "$work/restarted"
cp -r . "$work/restarted/bp5"
"$bin/frictionSolver" -case . >log.frictionSolver 2>&1
out=postProcessing/faultOutput
[[ $(ls $out/fltst_*.dat | wc -l) == 10 ]] || { echo "FAIL: 10 station files expected"; ls $out; exit 1; }
grep -q "^Setup: the surface stations' response to the slip (4 stations, 12 back-substitutions, once per run)" log.frictionSolver ||
  { echo "FAIL: no surface response line: $(grep -a "surface stations" log.frictionSolver)"; exit 1; }
/usr/bin/python3 - "$out" <<'PY'
# 3D surface stations: the format, the held faces exactly, the free surface above the event.
import re, sys
out = sys.argv[1]
row = re.compile(r"^ +-?\d\.\d{13}E[+-]\d\d( +-?\d\.\d{6}E[+-]\d\d){6}$")
data = {}
for name in ("srf_plus", "srf_minus", "srf_nucP", "srf_nucM"):
    lines = open(f"{out}/{name}.dat").read().splitlines()
    head = [l for l in lines if l.startswith("#")]
    assert len(head) == 8 and lines[8] == "t disp1 disp2 disp3 vel1 vel2 vel3", (name, lines[:10])
    assert "Displacement along z (m), positive upwards" in lines[4], lines[4]
    rows = lines[9:]
    assert len(rows) >= 100, (name, len(rows))
    for l in rows:
        assert row.match(l), (name, l)
    data[name] = [[float(v) for v in l.split()] for l in rows]
# The faces y = +-100 km are held: u = (+-V_p t/2, 0, 0), v = (+-V_p/2, 0, 0), to the 7 digits
# written (relative 5e-7) and round-off of the element's weights.
Vp = 1e-9
for name, sign in (("srf_plus", 1), ("srf_minus", -1)):
    for t, u1, u2, u3, v1, v2, v3 in data[name]:
        assert abs(u1 - sign * Vp * t / 2) <= 5e-7 * Vp * t / 2 + 1e-20, (name, t, u1)
        assert abs(v1 - sign * Vp / 2) <= 5e-7 * Vp / 2, (name, t, v1)
        assert max(abs(u2), abs(u3)) <= 1e-12 * max(Vp * t, 1e-20) + 1e-20, (name, t, u2, u3)
        assert max(abs(v2), abs(v3)) <= 1e-12 * Vp, (name, t, v2, v3)
# Above the nucleation zone, 1 km either side of the trace: the event moves the + side along +x
# and the - side along -x (right-lateral, as slip_2 > 0 at strk-24dp+10), by centimetres
# (slip 0.1 m and more at 10 km depth, 4 km below the velocity-weakening patch's top).
up, um = data["srf_nucP"][-1], data["srf_nucM"][-1]
# (Not antisymmetric to better than a factor 3 here: the points are 1 km off the trace in cells
# of 10 km, whose + and - sides are not mirror images; measured 0.034 and -0.100 m.)
assert up[1] > 1e-3 and um[1] < -1e-3, (up, um)
# At the end time the volume is solved: the stations' last rows (u_A + theta (u_B - u_A) +
# G (s - s_A), G by the adjoint) are the written displacement field interpolated at the points
# (VTK's own cell search and weights), to the 7 digits written.
import vtk
reader = vtk.vtkXMLUnstructuredGridReader()
reader.SetFileName("VTK/bp5_100000.vtu")
reader.Update()
grid = reader.GetOutput()
field = grid.GetPointData().GetArray("displacement")
points = {"srf_nucP": (-24000, 1000, 0), "srf_nucM": (-24000, -1000, 0)}
for name, p in points.items():
    found = None
    for cid in range(grid.GetNumberOfCells()):
        cell = grid.GetCell(cid)
        w = [0.0] * cell.GetNumberOfPoints()
        if cell.EvaluatePosition(p, [0, 0, 0], vtk.reference(0), [0, 0, 0], vtk.reference(0.0), w) == 1:
            found = [sum(w[k] * field.GetTuple3(cell.GetPointId(k))[j]
                         for k in range(cell.GetNumberOfPoints())) for j in range(3)]
            break
    assert found is not None, name
    last = data[name][-1]
    assert last[0] == 1e5, last
    scale = max(abs(x) for x in found)
    assert all(abs(a - b) <= 1e-6 * scale for a, b in zip(last[1:4], found)), (name, last, found)
print(f"PASS: surface stations: held faces at +-V_p t/2 exactly; above the event disp1 "
      f"{up[1]:.4g} and {um[1]:.4g} m at the end, the volume solution's there to 1e-6")
PY
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
# 10 stations, global.dat, rupture_1.dat and rupture_2.dat (bp5Case.py's ruptures yes), the
# surface stations, and the two time folders' states.
((n == 19)) || { echo "FAIL: $n files compared, 19 expected"; exit 1; }
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
refuse surface 's/^    surfaceStations .*/    surfaceStations { srf (0 1000); }/' \
  "controlDict:.*surface station 'srf': expected a point (x y z) on a 3D mesh"
refuse surfaceOutside 's/^    surfaceStations .*/    surfaceStations { srf (0 1000 5000); }/' \
  "controlDict:.*surface station 'srf' at (0, 1000, 5000): not in the body (no cell holds it)"
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
echo "PASS: 3D refusals (off the fault, no strike, strike down the dip, profiles, a 2D surface station, one outside, positiveSlip, an arclength, creepDirection normal to the fault)"

# Ruptures: the event files against global.dat and the stations, and a restart inside an event.
rm -rf "$work/rupture" && mkdir -p "$work/rupture"
cp -r "$work/full/bp5" "$work/rupture/full"
cd "$work/rupture/full"
rm -rf [1-9]* postProcessing VTK log.frictionSolver
grep -q "^    ruptures        yes;" system/controlDict || { echo "FAIL: bp5Case.py wrote no 'ruptures yes'"; exit 1; }
sed -i 's/^endTime .*/endTime 4400;/; s/^deltaT .*/deltaT 2200;/' system/controlDict
cp -r . "$work/rupture/restarted"
"$bin/frictionSolver" -case . >log.frictionSolver 2>&1
moved=$(grep -o "S of the right-hand side on the [0-9]* nodes that rate-and-state moves" log.frictionSolver | grep -o "[0-9]*")
[[ -n $moved ]] || { echo "FAIL: no count of moved nodes in the log"; exit 1; }
/usr/bin/python3 - postProcessing/faultOutput "$moved" "$src/tests/regression" <<'PY'
import math, os, re, sys
out, moved = sys.argv[1], int(sys.argv[2])
sys.path.insert(0, sys.argv[-1])
from ruptureFiles import rows, eventsAndFiles
events, files = eventsAndFiles(out)
assert files == ["rupture_%d.dat" % (k + 1) for k in range(len(events))] and len(events) == 2, \
    f"FAIL: files {files}, global.dat's events {events}"
station = rows(os.path.join(out, "fltst_strk-24dp+10.dat"))
for k, (t0, t1) in enumerate(events, 1):
    text = open(os.path.join(out, "rupture_%d.dat" % k)).read()
    m = re.search(r"event %d on fracture 'fault': onset (\S+) s, end (\S+) s" % k, text)
    assert m, f"FAIL: rupture_{k}.dat's header: {text[:200]}"
    onset, end = float(m.group(1)), float(m.group(2))
    assert abs(onset - t0) <= 1e-9 * max(1, t0) and abs(end - t1) <= 1e-9 * t1, \
        f"FAIL: event {k}: onset {onset} end {end} against global.dat's {t0} {t1}"
    assert text.splitlines()[2] == "x y z rupture_time slip_2 slip_3", "FAIL: column line"
    r = rows(os.path.join(out, "rupture_%d.dat" % k))
    assert len(r) == moved and all(len(x) == 6 for x in r), f"FAIL: {len(r)} rows, {moved} expected"
    hit = [x for x in r if not math.isnan(x[3])]
    assert hit and all(0 <= x[3] <= end - onset for x in hit), f"FAIL: event {k}: times {hit}"
    if k == 1:  # onset at 0: the nodes at V_init = 0.01 m/s, the nucleation zone's
        assert all(x[3] == 0 and -30e3 <= x[0] <= -18e3 and -16e3 <= x[2] <= -4e3 for x in hit), \
            f"FAIL: event 1's ruptured nodes {hit}"
    else:
        assert any(x[3] > 0 for x in hit), "FAIL: event 2 ruptured all at once"
        # The station's node (the nearest to (-24, 0, -10) km): its slip over the event is the
        # station file's, end row minus the last row before the onset (6 digits written).
        node = min(r, key=lambda x: (x[0] + 24e3) ** 2 + x[1] ** 2 + (x[2] + 10e3) ** 2)
        # (times written with 14 digits: the rows within 1e-12 of the header's times)
        before = [x for x in station if x[0] < onset * (1 - 1e-12)][-1]
        after = [x for x in station if abs(x[0] - end) <= 1e-12 * end]
        assert after, "FAIL: no station row at the event's end"
        for j, c in ((4, 1), (5, 2)):
            want = after[0][c] - before[c]
            assert abs(node[j] - want) <= 2e-6 * max(1, abs(want)), \
                f"FAIL: slip {node[j]} at the station's node against the station's {want}"
        assert node[4] > 0.1, f"FAIL: event 2 slipped {node[4]} m along strike at the station"
print(f"PASS: ruptures: {len(events)} events as global.dat's, {moved} nodes each")
PY
cd "$work/rupture/restarted"
sed -i 's/^endTime .*/endTime 2200;/' system/controlDict
"$bin/frictionSolver" -case . >log.1 2>&1
grep -q "^ *ruptureRunning yes;" 2200/uniform/frictionState || { echo "FAIL: 2200 s is not inside the second event"; exit 1; }
sed -i 's/^endTime .*/endTime 4400;/; s/^startTime .*/startTime 0;\nstartFrom latestTime;/' system/controlDict
"$bin/frictionSolver" -case . >log.2 2>&1
for f in "$work"/rupture/full/postProcessing/faultOutput/*.dat "$work"/rupture/full/[1-9]*/uniform/frictionState; do
  cmp -s "$f" "${f/full/restarted}" || { echo "FAIL: restarted inside the event, ${f#$work/rupture/} differs"; exit 1; }
done
echo "PASS: ruptures: stopped inside the second event and restarted, the same bytes"
rm -rf "$work/rupture/bad" && cp -r "$work/rupture/restarted" "$work/rupture/bad" && cd "$work/rupture/bad"
rm -rf [1-9]* postProcessing VTK log.*
sed -i '/^    stations$/,/^    }$/d; /^    strike /d' system/controlDict
rc=0
"$bin/frictionSolver" -case . >log 2>&1 || rc=$?
[[ $rc == 1 ]] && grep -q "'ruptures' in 3D need 'strike (x y z)'" log && grep -q "system/controlDict" log ||
  { echo "FAIL: ruptures without strike (exit $rc)"; cat log; exit 1; }
[[ -z $(ls -d [1-9]* 2>/dev/null) ]] || { echo "FAIL: a time folder written"; exit 1; }
echo "PASS: ruptures without strike refused"
