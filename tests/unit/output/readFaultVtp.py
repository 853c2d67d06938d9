#!/usr/bin/python3
"""Reads a 3D fault-surface .vtp (writeFractureVtp with triangles) with VTK itself
(python3-vtk9) and checks it against the fracture table of the same rows
(writeFractureTable, dim 3), as FractureOutputTest.cpp writes them:
  * VTK reads it without errors; point and cell counts; every cell a VTK_TRIANGLE (5)
    whose right-hand normal is the rows' normal (the orientation of the fault triangles);
  * cell areas by VTK's vtkCellSizeFilter: the first cell's and the total;
  * point data present with the right number of components: normal, slip, slipIncrement,
    traction (3); slipMagnitude, sigmaN, tauMagnitude, ST, residual (1); state (Int32);
  * the points and values equal the table's: normal = (nx ny nz), slip = (slipX slipY
    slipZ), slipIncrement = slipIncrement1 t1 + slipIncrement2 t2, traction = tau1 t1 +
    tau2 t2 (t1, t2 from the table's frame line), the scalars by name, state codes 0 stick,
    1 slip, 2 open, 3 tip; every value finite, the tips' too (the body's stress there).
Usage: readFaultVtp.py VTP DAT --points N --cells M [--firstArea A1] --area A --tips K
Exit status 0 when every check passes, 1 otherwise (each failure is printed).
"""
import argparse
import math
import re
import sys

try:
    from vtkmodules.vtkCommonCore import vtkCommand
    from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
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


# Relative tolerance of the comparisons: 1e-14 when both files hold 17 digits; a binary .vtp
# holds every digit while the table holds writePrecision (--tableDigits N: half a unit of the
# N-th digit, 5·10^-N, with a factor 2 for the sums of components).
TOLERANCE = 1e-14


def same(a, b, scale):
    """Equal to TOLERANCE of scale, NaN equal to NaN."""
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return abs(a - b) <= TOLERANCE * max(scale, 1e-300)


def readTable(path):
    with open(path) as f:
        text = f.read().splitlines()
    names = text[0].split()[1:]
    m = re.match(r"# frame n \((.*)\) t1 \((.*)\) t2 \((.*)\)$", text[2])
    if not check(m is not None, f"table: line 3 is a single frame ({text[2]})"):
        return names, None, []
    frame = [[float(x) for x in g.split()] for g in m.groups()]
    rows = []
    for line in text[3:]:
        w = line.split()
        rows.append({n: (w[i] if n == "state" else float(w[i])) for i, n in enumerate(names)})
    return names, frame, rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("vtp")
    ap.add_argument("dat")
    for key in ("points", "cells", "tips"):
        ap.add_argument("--" + key, type=int, required=True)
    ap.add_argument("--firstArea", type=float, help="omit to skip this check")
    ap.add_argument("--area", type=float, required=True)
    ap.add_argument("--tableDigits", type=int, default=17,
                    help="significant digits of the table (writePrecision); default 17")
    a = ap.parse_args()
    global TOLERANCE
    if a.tableDigits < 17:
        TOLERANCE = 1e-14 + 2 * 5 * 10.0 ** (-a.tableDigits)

    errors = []
    reader = vtkXMLPolyDataReader()
    reader.AddObserver(vtkCommand.ErrorEvent, lambda obj, ev: errors.append(ev))
    reader.SetFileName(a.vtp)
    reader.Update()
    p = reader.GetOutput()
    check(not errors, "VTK reads the .vtp without errors")
    nP, nC = p.GetNumberOfPoints(), p.GetNumberOfCells()
    check(nP == a.points, f"{nP} points (expected {a.points})")
    check(nC == a.cells and p.GetNumberOfPolys() == nC, f"{nC} cells, all polys (expected {a.cells})")
    if nP != a.points or nC != a.cells or nC == 0:
        return 1
    check(all(p.GetCellType(c) == 5 for c in range(nC)), "every cell is a VTK_TRIANGLE (5)")

    sizes = vtkCellSizeFilter()
    sizes.SetInputData(p)
    sizes.SetComputeVertexCount(False)
    sizes.SetComputeLength(False)
    sizes.SetComputeArea(True)
    sizes.SetComputeVolume(False)
    sizes.Update()
    area = vtk_to_numpy(sizes.GetOutput().GetCellData().GetArray("Area"))
    if a.firstArea is not None:
        check(abs(area[0] - a.firstArea) <= 1e-12 * a.firstArea,
              f"first cell's area {area[0]:.17g} (expected {a.firstArea:.17g})")
    check(abs(area.sum() - a.area) <= 1e-12 * a.area,
          f"total area {area.sum():.17g} (expected {a.area:.17g})")

    names, frame, rows = readTable(a.dat)
    if not check(frame is not None and len(rows) == nP, f"table: {len(rows)} rows, one per point"):
        return 1
    n, t1, t2 = frame
    pts = vtk_to_numpy(p.GetPoints().GetData())
    check(all(same(pts[i][d], rows[i]["xyz"[d]], 1.0) for i in range(nP) for d in range(3)),
          "points = the table's x y z, in row order")
    badOrient = 0
    for c in range(nC):
        ids = p.GetCell(c).GetPointIds()
        P = [pts[ids.GetId(k)] for k in range(3)]
        u = [P[1][d] - P[0][d] for d in range(3)]
        v = [P[2][d] - P[0][d] for d in range(3)]
        cr = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        badOrient += sum(cr[d] * n[d] for d in range(3)) <= 0
    check(badOrient == 0, f"every cell's right-hand normal along n ({badOrient} bad)")

    pd = p.GetPointData()
    want = {"normal": 3, "slip": 3, "slipIncrement": 3, "traction": 3, "slipMagnitude": 1,
            "sigmaN": 1, "tauMagnitude": 1, "ST": 1, "residual": 1, "state": 1}
    arrays = {}
    for key, comps in want.items():
        arr = pd.GetArray(key)
        if check(arr is not None and arr.GetNumberOfComponents() == comps
                 and arr.GetNumberOfTuples() == nP, f"point array {key}, {comps} component(s)"):
            arrays[key] = vtk_to_numpy(arr)
    if len(arrays) != len(want):
        return 1
    check(pd.GetArray("state").GetDataTypeAsString() == "int", "state is an int array")

    def inXyz(c1, c2):
        return [c1 * t1[d] + c2 * t2[d] for d in range(3)]

    vectors = {
        "normal": lambda r: [r["nx"], r["ny"], r["nz"]],
        "slip": lambda r: [r["slipX"], r["slipY"], r["slipZ"]],
        "slipIncrement": lambda r: inXyz(r["slipIncrement1"], r["slipIncrement2"]),
        "traction": lambda r: inXyz(r["tau1"], r["tau2"]),
    }
    for key, f in vectors.items():
        bad = 0
        for i, r in enumerate(rows):
            w = f(r)
            scale = max(abs(x) for x in w) if not any(math.isnan(x) for x in w) else 1.0
            bad += any(not same(arrays[key][i][d], w[d], scale) for d in range(3))
        check(bad == 0, f"{key} = the table's ({bad} bad)")
    for key in ("slipMagnitude", "sigmaN", "tauMagnitude", "ST", "residual"):
        bad = sum(not same(arrays[key][i], r[key], abs(r[key]) if not math.isnan(r[key]) else 1)
                  for i, r in enumerate(rows))
        check(bad == 0, f"{key} = the table's ({bad} bad)")
    codes = {"stick": 0, "slip": 1, "open": 2, "tip": 3}
    check([int(x) for x in arrays["state"]] == [codes[r["state"]] for r in rows],
          "state codes = the table's states")
    tips = [i for i, r in enumerate(rows) if r["state"] == "tip"]
    check(len(tips) == a.tips, f"{len(tips)} tip(s) (expected {a.tips})")
    finite = all(math.isfinite(x) for key in arrays for x in arrays[key].ravel())
    check(finite, "every value of every point array finite (tips included)")
    print(f"{len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
