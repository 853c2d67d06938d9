#!/usr/bin/python3
"""Checks cases/pennyCrack/pennyError.py on synthetic results made from the formula itself.

Usage: pennyErrorSynthetic.py SOURCE_DIR WORK_DIR

From the case's committed gmsh mesh (its fault triangles), writes 3D fracture tables and
fault-surface .vtp files in the layout frictionSolver writes (docs: README.md, 3D tables),
P1 and P2 (a .vtp holds linear cells only: frictionSolver writes a P2 triangle as the four
triangles at its edge midpoints), whose slip is the analytic one (times a factor), and checks what pennyError.py
prints:
  * nodal values = formula: the lumped error is 0 (to rounding) and the amplitude ratio 1,
    the integrated error is the interpolation error of sqrt(a^2 - r^2) alone (small,
    smaller for P2), the angles and the law deviation 0 (to the table's 12 digits);
  * nodal values = 1.01 x formula: the lumped error is 0.01 and the amplitude ratio 1.01;
  * one node's slip turned by 5 degrees in the plane: the largest angle is 5 degrees and
    --maxAngle 1 fails (exit 3);
  * |tau| off the friction bound by 1e-3 at one node: maxLawDeviation is 1e-3;
  * a 2D table, a missing .vtp: exit 1 with a message.
"""

import math
import os
import shutil
import subprocess
import sys

import numpy as np

src, work = sys.argv[1], sys.argv[2]
caseSrc = os.path.join(src, "cases", "pennyCrack")
script = os.path.join(caseSrc, "pennyError.py")
failures = []


def fail(msg):
    print("FAIL:", msg)
    failures.append(msg)


def readMsh41(path):
    """Nodes {tag: xyz} and the triangles of physical surface 5 ("fault")."""
    lines = open(path).read().split("\n")
    i, nodes, faultEntities, tris = 0, {}, set(), []
    while i < len(lines):
        l = lines[i].strip()
        if l == "$Entities":
            npt, nc, ns, nv = map(int, lines[i + 1].split())
            j = i + 2 + npt + nc
            for k in range(ns):
                f = lines[j + k].split()
                if 5 in [int(x) for x in f[8:8 + int(f[7])]]:
                    faultEntities.add(int(f[0]))
            i = j + ns + nv
        elif l == "$Nodes":
            nb = int(lines[i + 1].split()[0])
            j = i + 2
            for _ in range(nb):
                cnt = int(lines[j].split()[3])
                tags = [int(lines[j + 1 + k]) for k in range(cnt)]
                for k in range(cnt):
                    nodes[tags[k]] = [float(x) for x in lines[j + 1 + cnt + k].split()]
                j += 1 + 2 * cnt
            i = j
        elif l == "$Elements":
            nb = int(lines[i + 1].split()[0])
            j = i + 2
            for _ in range(nb):
                d, t, et, cnt = map(int, lines[j].split())
                if d == 2 and t in faultEntities:
                    tris += [list(map(int, lines[j + 1 + k].split()))[1:4] for k in range(cnt)]
                j += 1 + cnt
            i = j
        else:
            i += 1
    return nodes, tris


nodes, tris = readMsh41(os.path.join(caseSrc, "constant", "mesh", "pennyCrack.msh"))
assert tris, "no fault triangles in the committed mesh"
E, nu, muF = 10e9, 0.25, 0.3            # the case's dictionaries (copied below)
s = [-12e6, -8e6, -10e6, 1e6, 3.6e6, 4.8e6]
sigma0 = np.array([[s[0], s[3], s[5]], [s[3], s[1], s[4]], [s[5], s[4], s[2]]])
G = E / (2 * (1 + nu))


def makeCase(name, order, factor=1.0, turnOne=0.0, lawOffOne=0.0, table2D=False, vtp=True,
             rimMidpointsSlip=False):
    case = os.path.join(work, name)
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(os.path.join(caseSrc, "constant"), os.path.join(case, "constant"),
                    ignore=shutil.ignore_patterns("mesh", "splitMesh"))
    # rows: the fault's nodes by ascending node number, then (P2) the edge midpoints
    ids = sorted({v for t in tris for v in t})
    row = {v: k for k, v in enumerate(ids)}
    xyz = [nodes[v] for v in ids]
    cells = [[row[v] for v in t] for t in tris]
    edgeCount = {}
    for t in tris:
        for e in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            key = tuple(sorted(e))
            edgeCount[key] = edgeCount.get(key, 0) + 1
    rim = {v for e, c in edgeCount.items() if c == 1 for v in e}
    tip = [v in rim for v in ids]
    if order == 2:
        mid = {}
        for e in sorted(edgeCount):
            mid[e] = len(xyz)
            xyz.append(list((np.array(nodes[e[0]]) + np.array(nodes[e[1]])) / 2))
            tip.append(False)   # a rim edge's midpoint is a tip node too (below)
            if edgeCount[e] == 1 and not rimMidpointsSlip:
                tip[-1] = True
        cells = [c + [mid[tuple(sorted((t[0], t[1])))], mid[tuple(sorted((t[1], t[2])))],
                      mid[tuple(sorted((t[2], t[0])))]] for c, t in zip(cells, tris)]
    xyz = np.array(xyz)
    n = np.array([0.0, 0.0, -1.0])
    t1 = np.array([1.0, 0.0, 0.0])           # the axis least aligned with n, projected
    t2 = np.cross(n, t1)
    trac = sigma0 @ n
    sn = trac @ n
    tauInf = trac - sn * n
    dtau = np.linalg.norm(tauInf) - muF * abs(sn)
    amp = 8 * (1 - nu) * dtau / (math.pi * (2 - nu) * G)
    r = np.linalg.norm(xyz[:, :2], axis=1)
    mag = factor * amp * np.sqrt(np.maximum(1 - r * r, 0))
    dirSlip = -tauInf / np.linalg.norm(tauInf)
    lines = []
    first = True
    for k, (x, isTip) in enumerate(zip(xyz, tip)):
        if isTip:
            sv = np.zeros(3)
            vals = [math.nan] * 6
            state = "tip"
        else:
            d = dirSlip
            if first and turnOne and r[k] < 0.5:
                c, sn5 = math.cos(math.radians(turnOne)), math.sin(math.radians(turnOne))
                d = c * dirSlip + sn5 * np.cross(n, dirSlip)
            sv = mag[k] * d
            bound = muF * abs(sn)
            tau = bound * (1 + (lawOffOne if first and r[k] < 0.5 else 0)) * -dirSlip
            if r[k] < 0.5 and (turnOne or lawOffOne):
                first = False
            vals = [sn, tau @ t1, tau @ t2, np.linalg.norm(tau),
                    np.linalg.norm(tau) / abs(sn), 1e-12]
            state = "slip"
        s1, s2 = sv @ t1, sv @ t2
        v = list(x) + list(n) + [s1, s2] + list(sv) + [np.linalg.norm(sv), s1, s2] + vals
        lines.append(" ".join(f"{q:.12g}" for q in v) + " " + state)
    os.makedirs(os.path.join(case, "1", "fractures"))
    with open(os.path.join(case, "1", "fractures", "fault.dat"), "w") as f:
        if table2D:
            f.write("# s x y slip slipIncrement sigmaN tau ST residual state\n# status converged\n")
        else:
            f.write("# x y z nx ny nz slip1 slip2 slipX slipY slipZ slipMagnitude "
                    "slipIncrement1 slipIncrement2 sigmaN tau1 tau2 tauMagnitude ST residual "
                    "state\n# status converged iterations 1\n")
            f.write(f"# frame n ({' '.join(map(str, n))}) t1 ({' '.join(map(str, t1))}) "
                    f"t2 ({' '.join(f'{q:g}' for q in t2)})\n")
            f.write("\n".join(lines) + "\n")
    if vtp:
        import vtk
        pts = vtk.vtkPoints()
        pts.SetDataTypeToDouble()
        for x in xyz:
            pts.InsertNextPoint(*x)
        poly = vtk.vtkPolyData()
        poly.SetPoints(pts)
        ca = vtk.vtkCellArray()
        for c in cells:
            if order == 1:
                ca.InsertNextCell(3, c)
            else:   # as frictionSolver writes a P2 triangle: four at its edge midpoints
                for sub in ((0, 3, 5), (3, 1, 4), (5, 4, 2), (3, 4, 5)):
                    ca.InsertNextCell(3, [c[k] for k in sub])
        poly.SetPolys(ca)
        os.makedirs(os.path.join(case, "VTK", "fractures"))
        w = vtk.vtkXMLPolyDataWriter()
        w.SetFileName(os.path.join(case, "VTK", "fractures", "fault_1.vtp"))
        w.SetInputData(poly)
        w.Write()
    return case


def run(case, *extra):
    p = subprocess.run([sys.executable, script, "-case", case, *extra], capture_output=True,
                       text=True)
    vals = {}
    for line in p.stdout.splitlines():
        k, _, v = line.partition("  ")
        vals[k.strip()] = v.strip()
    print(f"--- {os.path.basename(case)} {' '.join(extra)}: exit {p.returncode}")
    print(p.stdout + p.stderr)
    return p.returncode, vals, p.stdout + p.stderr


def num(vals, key):
    return float(vals[key].split()[0])


shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
interp = {}
for order in (1, 2):
    # P2: the rim edges' midpoints lie inside the circle, where the formula is not 0; giving
    # them the formula's value (and state slip) makes every node exact, so the lumped error
    # checks the P1-iso-P2 weights' arithmetic.
    rc, v, _ = run(makeCase(f"exactP{order}", order, rimMidpointsSlip=True), "--maxError",
                   "0.1", "--maxAngle", "1e-6", "--maxLaw", "1e-10")
    if rc != 0:
        fail(f"P{order} exact: exit {rc}")
        continue
    if v["elements"].split()[0] != f"P{order}":
        fail(f"P{order} exact: elements '{v['elements']}'")
    if not num(v, "relL2ErrorLumped") < 1e-10:   # the table's 12 digits
        fail(f"P{order} exact: lumped error {v['relL2ErrorLumped']} (expected 0)")
    interp[order] = num(v, "relL2Error")
    if not 0 < interp[order] < 0.1:   # h = a/8: P1 0.055, P2 0.015 measured
        fail(f"P{order} exact: integrated error {interp[order]} (interpolation error only)")
    if abs(num(v, "amplitudeRatio") - 1) > 1e-10:
        fail(f"P{order} exact: amplitude ratio {v['amplitudeRatio']}")
    if not int(v["innerSlipNodes"].split()[0]) > 0:
        fail(f"P{order} exact: no inner slip nodes")
    if abs(float(v["disc"].split("radius")[1].split()[0]) - 1) > 1e-9:
        fail(f"P{order} exact: radius {v['disc']}")
    if not num(v, "frameConsistency") < 1e-9:
        fail(f"P{order} exact: frame consistency {v['frameConsistency']}")
    if not abs(float(v["centreSlipExact"].split()[0]) - 8.18511e-4) < 1e-8:
        fail(f"P{order} exact: centre slip {v['centreSlipExact']} (8(1-nu)dtau a/(pi(2-nu)G) "
             "= 8.18511e-4 m for dtau = 3 MPa, G = 4 GPa)")
if len(interp) == 2 and not interp[2] < interp[1]:
    fail(f"P2 interpolation error {interp[2]} not below P1's {interp[1]}")

rc, v, _ = run(makeCase("scaled", 1, factor=1.01))
if rc != 0 or abs(num(v, "relL2ErrorLumped") - 0.01) > 1e-9 or \
        abs(num(v, "amplitudeRatio") - 1.01) > 1e-10:
    fail(f"scaled by 1.01: exit {rc}, {v.get('relL2ErrorLumped')}, {v.get('amplitudeRatio')}")

rc, v, _ = run(makeCase("turned", 1, turnOne=5.0), "--maxAngle", "1")
if rc != 3 or abs(num(v, "maxAngleSlipRemoteShear") - 5) > 1e-6 or \
        abs(num(v, "maxAngleSlipMinusTau") - 5) > 1e-6:
    fail(f"one node turned by 5 deg: exit {rc} (expected 3), {v.get('maxAngleSlipRemoteShear')}")

rc, v, _ = run(makeCase("lawOff", 1, lawOffOne=1e-3), "--maxLaw", "1e-6")
if rc != 3 or abs(num(v, "maxLawDeviation") - 1e-3) > 1e-9:
    fail(f"|tau| off by 1e-3: exit {rc} (expected 3), {v.get('maxLawDeviation')}")

rc, _, out = run(makeCase("table2D", 1, table2D=True))
if rc != 1 or "a 2D fracture table" not in out:
    fail(f"2D table: exit {rc} (expected 1 with 'a 2D fracture table')")

rc, _, out = run(makeCase("noVtp", 1, vtp=False))
if rc != 1 or "fault_1.vtp: not found" not in out:
    fail(f"missing .vtp: exit {rc} (expected 1 naming the file)")

rc, _, out = run(makeCase("badOption", 1), "--maxError")
if rc != 2:
    fail(f"bad command line: exit {rc} (expected 2)")

if failures:
    sys.exit(1)
# The work folders hold results compared across builds (byte for byte): leave nothing here.
shutil.rmtree(work, ignore_errors=True)
print("PASS: pennyError.py on synthetic results")
