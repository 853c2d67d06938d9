#!/usr/bin/python3
"""Reads the VTK output of VtkWriterTest.cpp with VTK itself (python3-vtk9) and checks it.

The test writes, at each time t of a .pvd, the displacement t * (A x + b + c [x in Omega+])
on a unit-square split mesh with a horizontal fracture at y = yF (Omega+ above it), and a
synthetic fracture table (formulas in fractureRows below). This script parses the .pvd with
xml.etree (VTK's Python has no vtkPVDReader), reads every file it names with VTK's XML
readers and checks:
  * point and cell counts, the cell type (5 or 22), connectivity in range (VTK does not),
    counter-clockwise cells and, for P2, that nodes 3 4 5 are the midpoints of 0-1, 1-2, 2-0;
  * the displacement at every node, on the side of the cell that uses it (so the two
    coincident copies of a fracture node carry the two sides' values);
  * the stress of the linear field, exactly (Hooke's law written again here, independently
    of the C++ Material), and von Mises;
  * the fracture polyline and its arrays, and that state is an integer array.
With --dim 3 the .vtu holds a tetrahedral mesh of the unit cube (no fracture, no .vtp) and
the displacement t * (b + G x); the script checks the counts, the cell type (10 or 24),
connectivity in range, positive cell volumes (VTK's vtkCellSizeFilter) summing to 1, for P2
that every edge VTK itself takes from the cell (vtkCell.GetEdge) has its middle node at the
midpoint, the displacement at every point, the 3D Hooke stress of sym G in every cell,
von Mises and region = 1 + cell % 3.
Usage: readVtk.py PVD --E E --nu NU [--planeStress] --A a11 a12 a21 a22 --b b1 b2
                  --jump c1 c2 --fractureY Y --points N --cells M --degree 1|2
                  --fracturePoints m --times n
       readVtk.py PVD --dim 3 --E E --nu NU --G g11 g12 g13 g21 .. g33 --b b1 b2 b3
                  --points N --cells M --degree 1|2 --fracturePoints 0 --times n
Exit status 0 when every check passes, 1 otherwise (each failure is printed).
"""
import argparse
import math
import os
import sys
import xml.etree.ElementTree as ET

try:
    from vtkmodules.vtkCommonCore import vtkCommand
    from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLUnstructuredGridReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError as e:  # the test must fail, not skip, without VTK
    print(f"FAIL: cannot import vtk ({e}); install python3-vtk9", file=sys.stderr)
    sys.exit(1)

failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        failures.append(what)
    return ok


def close(a, b, tol):
    return abs(a - b) <= tol


def read(readerClass, path):
    errors = []
    reader = readerClass()
    reader.AddObserver(vtkCommand.ErrorEvent, lambda obj, ev: errors.append(ev))
    reader.SetFileName(path)
    reader.Update()
    check(not errors, f"{os.path.basename(path)}: VTK reads it without errors")
    return reader.GetOutput()


def fractureRows(m):
    """The rows VtkWriterTest.cpp writes (keep in step with fractureRows there)."""
    rows = []
    for i in range(m):
        s = i / (m - 1)
        sigmaN = -1e6 * (1 + s)
        tau = 1e5 * s
        rows.append(dict(s=s, x=s, y=None, slip=1e-3 * s, slipIncrement=2e-4 * s,
                         sigmaN=sigmaN, tau=tau, ST=abs(tau) / -sigmaN, residual=1e-9 * i,
                         state=i % 3))
    return rows


def readCells(path, a, per, wantType):
    """The grid at path with its counts, point coordinates and cells checked (per nodes of VTK
    type wantType each, connectivity in range, every point used): (g, name, pts, conn, offs), or
    None when there is nothing more to check."""
    g = read(vtkXMLUnstructuredGridReader, path)
    name = os.path.basename(path)
    nP, nC = g.GetNumberOfPoints(), g.GetNumberOfCells()
    check(nP == a.points, f"{name}: {nP} points (expected {a.points})")
    check(nC == a.cells, f"{name}: {nC} cells (expected {a.cells})")
    if nP == 0 or nC == 0:
        return None
    pts = vtk_to_numpy(g.GetPoints().GetData())
    conn = vtk_to_numpy(g.GetCells().GetConnectivityArray())
    offs = vtk_to_numpy(g.GetCells().GetOffsetsArray())
    types = vtk_to_numpy(g.GetCellTypesArray())
    check(all(int(x) == wantType for x in types), f"{name}: every cell has VTK type {wantType}")
    check(len(offs) == nC + 1 and all(offs[i + 1] - offs[i] == per for i in range(nC)),
          f"{name}: every cell has {per} nodes")
    if not check(len(conn) == per * nC and conn.min() >= 0 and conn.max() < nP,
                 f"{name}: connectivity in range [0, {nP}) (min {conn.min()}, max {conn.max()})"):
        return None
    check(len(set(int(x) for x in conn)) == nP, f"{name}: every point is used by a cell")
    return g, name, pts, conn, offs


def checkVtu(path, t, a):
    per = 3 if a.degree == 1 else 6
    got = readCells(path, a, per, 5 if a.degree == 1 else 22)
    if got is None:
        return
    g, name, pts, conn, offs = got
    nP, nC = g.GetNumberOfPoints(), g.GetNumberOfCells()

    disp = g.GetPointData().GetArray("displacement")
    stress = g.GetCellData().GetArray("stress")
    vm = g.GetCellData().GetArray("vonMises")
    if not (check(disp is not None and disp.GetNumberOfComponents() == 3,
                  f"{name}: point array displacement, 3 components")
            and check(stress is not None and stress.GetNumberOfComponents() == 6,
                      f"{name}: cell array stress, 6 components")
            and check(vm is not None and vm.GetNumberOfComponents() == 1,
                      f"{name}: cell array vonMises")):
        return
    check(g.GetCellData().GetTensors() is not None
          and g.GetCellData().GetTensors().GetName() == "stress",
          f"{name}: stress is the cell data's tensor attribute")
    check(g.GetPointData().GetVectors() is not None, f"{name}: displacement is the vectors attribute")
    U = vtk_to_numpy(disp)
    S = vtk_to_numpy(stress)
    VM = vtk_to_numpy(vm)

    A, b, c = a.A, a.b, a.jump
    scale = max(1e-300, max(abs(v) for v in A + b + c)) * t
    badShape = badU = 0
    for k in range(nC):
        nodes = [int(x) for x in conn[offs[k]:offs[k + 1]]]
        P = [pts[n] for n in nodes]
        area = 0.5 * ((P[1][0] - P[0][0]) * (P[2][1] - P[0][1])
                      - (P[2][0] - P[0][0]) * (P[1][1] - P[0][1]))
        if area <= 0:
            badShape += 1
        if per == 6:
            for m, (i, j) in zip((3, 4, 5), ((0, 1), (1, 2), (2, 0))):
                if any(abs(P[m][d] - 0.5 * (P[i][d] + P[j][d])) > 1e-12 for d in range(3)):
                    badShape += 1
        yc = (P[0][1] + P[1][1] + P[2][1]) / 3
        plus = 1.0 if yc > a.fractureY else 0.0
        for n in nodes:
            x, y = pts[n][0], pts[n][1]
            ux = t * (A[0] * x + A[1] * y + b[0] + plus * c[0])
            uy = t * (A[2] * x + A[3] * y + b[1] + plus * c[1])
            if not (close(U[n][0], ux, 1e-12 * scale) and close(U[n][1], uy, 1e-12 * scale)
                    and U[n][2] == 0):
                badU += 1
    check(badShape == 0, f"{name}: cells counter-clockwise" +
          (", P2 nodes 3 4 5 at mid(0,1) mid(1,2) mid(2,0)" if per == 6 else "") +
          f" ({badShape} bad)")
    check(badU == 0, f"{name}: displacement = t (A x + b + c [Omega+]) at every node of every"
          f" cell, both sides of the fracture ({badU} bad)")

    # Hooke's law, independently of the C++ Material.
    E, nu = a.E, a.nu
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    exx, eyy, exy = t * A[0], t * A[3], 0.5 * t * (A[1] + A[2])
    if a.planeStress:
        lamStar = 2 * lam * mu / (lam + 2 * mu)
        szz = 0.0
    else:
        lamStar = lam
        szz = lam * (exx + eyy)
    sxx = lamStar * (exx + eyy) + 2 * mu * exx
    syy = lamStar * (exx + eyy) + 2 * mu * eyy
    sxy = 2 * mu * exy
    want = [sxx, syy, szz, sxy, 0.0, 0.0]
    wantVm = math.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2)
                       + 3 * sxy ** 2)
    # The field is linear, so the FE stress is exact up to round-off and the written digits.
    tol = 1e-9 * max(abs(v) for v in want)
    badS = sum(1 for k in range(nC) if any(not close(S[k][i], want[i], tol) for i in range(6)))
    check(badS == 0, f"{name}: stress (xx yy zz xy yz xz) = {['%.6g' % v for v in want]} in"
          f" every cell ({badS} bad)")
    check(all(close(v, wantVm, tol) for v in VM), f"{name}: von Mises = {wantVm:.6g} in every cell")


def checkVtu3d(path, t, a):
    per = 4 if a.degree == 1 else 10
    got = readCells(path, a, per, 10 if a.degree == 1 else 24)
    if got is None:
        return
    g, name, pts, conn, offs = got
    nP, nC = g.GetNumberOfPoints(), g.GetNumberOfCells()

    # Cell validity as VTK sees it: volumes (for P2 by VTK's own subdivision of the quadratic
    # cell) positive and filling the unit cube; for P2 each of VTK's quadratic edges has its
    # middle node at the midpoint of its ends (a node order other than VTK's breaks that).
    sizes = vtkCellSizeFilter()
    sizes.SetInputData(g)
    sizes.SetComputeVertexCount(False)
    sizes.SetComputeLength(False)
    sizes.SetComputeArea(False)
    sizes.SetComputeVolume(True)
    sizes.Update()
    vol = vtk_to_numpy(sizes.GetOutput().GetCellData().GetArray("Volume"))
    check(len(vol) == nC and vol.min() > 0, f"{name}: every cell volume > 0 (min {vol.min():.3g})")
    check(close(float(vol.sum()), 1.0, 1e-12), f"{name}: volumes sum to 1 ({vol.sum():.17g})")
    if per == 10:
        badEdge = 0
        for k in range(nC):
            cell = g.GetCell(k)
            badEdge += cell.GetNumberOfEdges() != 6
            for e in range(cell.GetNumberOfEdges()):
                ids = cell.GetEdge(e).GetPointIds()
                p0, p1, m = (pts[ids.GetId(i)] for i in range(3))
                if any(abs(m[d] - 0.5 * (p0[d] + p1[d])) > 1e-12 for d in range(3)):
                    badEdge += 1
        check(badEdge == 0, f"{name}: the middle node of every VTK edge at its midpoint"
              f" ({badEdge} bad)")

    disp = g.GetPointData().GetArray("displacement")
    stress = g.GetCellData().GetArray("stress")
    vm = g.GetCellData().GetArray("vonMises")
    region = g.GetCellData().GetArray("region")
    if not (check(disp is not None and disp.GetNumberOfComponents() == 3,
                  f"{name}: point array displacement, 3 components")
            and check(stress is not None and stress.GetNumberOfComponents() == 6,
                      f"{name}: cell array stress, 6 components")
            and check(vm is not None, f"{name}: cell array vonMises")
            and check(region is not None, f"{name}: cell array region")):
        return
    U = vtk_to_numpy(disp)
    S = vtk_to_numpy(stress)
    VM = vtk_to_numpy(vm)
    R = vtk_to_numpy(region)
    G, b = a.G, a.b
    scale = max(abs(v) for v in G + b) * t
    badU = 0
    for n in range(nP):
        x = pts[n]
        for i in range(3):
            ui = t * (b[i] + sum(G[3 * i + j] * x[j] for j in range(3)))
            if not close(U[n][i], ui, 1e-12 * scale):
                badU += 1
    check(badU == 0, f"{name}: displacement = t (b + G x) at every point ({badU} bad)")

    # Hooke's law in 3D, independently of the C++ Material.
    E, nu = a.E, a.nu
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    eps = [[0.5 * t * (G[3 * i + j] + G[3 * j + i]) for j in range(3)] for i in range(3)]
    tr = eps[0][0] + eps[1][1] + eps[2][2]
    sig = [[lam * tr * (i == j) + 2 * mu * eps[i][j] for j in range(3)] for i in range(3)]
    want = [sig[0][0], sig[1][1], sig[2][2], sig[0][1], sig[1][2], sig[0][2]]
    sxx, syy, szz, sxy, syz, sxz = want
    wantVm = math.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2)
                       + 3 * (sxy ** 2 + syz ** 2 + sxz ** 2))
    # The field is linear, so the FE stress is exact up to round-off and the written digits.
    tol = 1e-10 * max(abs(v) for v in want)
    badS = sum(1 for k in range(nC) if any(not close(S[k][i], want[i], tol) for i in range(6)))
    check(badS == 0, f"{name}: stress (xx yy zz xy yz xz) = {['%.6g' % v for v in want]} in"
          f" every cell ({badS} bad)")
    check(all(close(v, wantVm, 1e-10 * wantVm) for v in VM),
          f"{name}: von Mises = {wantVm:.6g} in every cell")
    check(all(int(R[k]) == 1 + k % 3 for k in range(nC)), f"{name}: region = 1 + cell % 3")


def checkVtp(path, t, a):
    p = read(vtkXMLPolyDataReader, path)
    name = os.path.basename(path)
    m = a.fracturePoints
    check(p.GetNumberOfPoints() == m, f"{name}: {p.GetNumberOfPoints()} points (expected {m})")
    check(p.GetNumberOfLines() == 1 and p.GetNumberOfCells() == 1, f"{name}: one polyline")
    if p.GetNumberOfPoints() != m or p.GetNumberOfCells() != 1:
        return
    check(p.GetCellType(0) == 4, f"{name}: cell type VTK_POLY_LINE (4)")
    ids = p.GetCell(0).GetPointIds()
    check([ids.GetId(i) for i in range(ids.GetNumberOfIds())] == list(range(m)),
          f"{name}: the polyline runs through the points in row order")
    pts = vtk_to_numpy(p.GetPoints().GetData())
    rows = fractureRows(m)
    check(all(close(pts[i][0], rows[i]["x"], 1e-12) and close(pts[i][1], a.fractureY, 1e-12)
              and pts[i][2] == 0 for i in range(m)), f"{name}: points (s, yF, 0)")
    pd = p.GetPointData()
    for key in ("s", "slip", "slipIncrement", "sigmaN", "tau", "ST", "residual"):
        arr = pd.GetArray(key)
        if not check(arr is not None and arr.GetNumberOfTuples() == m, f"{name}: array {key}"):
            continue
        v = vtk_to_numpy(arr)
        # Quantities scale with t except s (geometry) and ST (a ratio).
        f = 1.0 if key in ("s", "ST") else t
        check(all(close(v[i], f * rows[i][key], 1e-12 * max(1.0, abs(f * rows[i][key])))
                  for i in range(m)), f"{name}: {key} values")
    st = pd.GetArray("state")
    if check(st is not None, f"{name}: array state"):
        check(st.GetDataTypeAsString() == "int", f"{name}: state is an int array"
              f" ({st.GetDataTypeAsString()})")
        v = vtk_to_numpy(st)
        check([int(x) for x in v] == [r["state"] for r in rows],
              f"{name}: state codes 0 stick, 1 slip, 2 open")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("pvd")
    ap.add_argument("--E", type=float, required=True)
    ap.add_argument("--nu", type=float, required=True)
    ap.add_argument("--dim", type=int, choices=(2, 3), default=2)
    ap.add_argument("--planeStress", action="store_true")
    ap.add_argument("--A", type=float, nargs=4)
    ap.add_argument("--G", type=float, nargs=9)
    ap.add_argument("--b", type=float, nargs="+", required=True)
    ap.add_argument("--jump", type=float, nargs=2)
    ap.add_argument("--fractureY", type=float)
    ap.add_argument("--points", type=int, required=True)
    ap.add_argument("--cells", type=int, required=True)
    ap.add_argument("--degree", type=int, choices=(1, 2), required=True)
    ap.add_argument("--fracturePoints", type=int, required=True)
    ap.add_argument("--times", type=int, required=True)
    a = ap.parse_args()
    if a.dim == 2 and (a.A is None or a.jump is None or a.fractureY is None or len(a.b) != 2):
        ap.error("2D needs --A, --jump, --fractureY and two --b values")
    if a.dim == 3 and (a.G is None or len(a.b) != 3):
        ap.error("--dim 3 needs --G and three --b values")

    try:
        root = ET.parse(a.pvd).getroot()
    except (OSError, ET.ParseError) as e:
        check(False, f"{a.pvd}: parses as XML ({e})")
        return 1
    check(root.tag == "VTKFile" and root.get("type") == "Collection", "pvd: a VTK Collection")
    sets = root.findall("./Collection/DataSet")
    times = sorted({float(d.get("timestep")) for d in sets})
    check(len(times) == a.times, f"pvd: {len(times)} times (expected {a.times})")
    base = os.path.dirname(os.path.abspath(a.pvd))
    for t in times:
        parts = sorted((int(d.get("part")), d.get("file")) for d in sets
                       if float(d.get("timestep")) == t)
        wantParts = [0, 1] if a.dim == 2 else [0]
        check([k for k, _ in parts] == wantParts, f"pvd: time {t} has parts {wantParts}")
        for part, rel in parts:
            path = os.path.join(base, rel)
            if not check(os.path.isfile(path), f"pvd: time {t} part {part}: {rel} exists"):
                continue
            if part == 0:
                check(rel.endswith(".vtu"), f"pvd: part 0 is the .vtu")
                (checkVtu if a.dim == 2 else checkVtu3d)(path, t, a)
            else:
                check(rel.endswith(".vtp"), f"pvd: part {part} is a fracture .vtp")
                checkVtp(path, t, a)
    print(f"{len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
