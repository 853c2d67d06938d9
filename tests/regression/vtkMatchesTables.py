#!/usr/bin/python3
"""The solver's VTK files, read with real VTK, hold what its own tables hold.

Usage: vtkMatchesTables.py CASE_DIR TIME FRACTURE NUM_POINTS NUM_CELLS
Checks: the .pvd names files that exist; the .vtu has the split mesh's point and cell
counts, connectivity in range (VTK itself does not check it) and finite arrays; the .vtp
has one point per table row with sigmaN, tau, ST, slip, residual, opening (fractures that
open), pressure, sigmaNEffective and deltaCFS (a fluid pressure), normal and tangent (nx ny
and tx ty, z = 0) and state equal to the table's values (the table is written with
writePrecision digits: relative 1e-6 is ample); every value of both is finite (a tip's row
gives the body's stress there), and a tip has state code 3.
"""
import math
import os
import sys
import xml.etree.ElementTree as ET

import vtk
from vtk.util.numpy_support import vtk_to_numpy

case, time, fracture, npoints, ncells = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5])
vtkdir = os.path.join(case, "VTK")
pvds = [f for f in os.listdir(vtkdir) if f.endswith(".pvd")]
assert len(pvds) == 1, pvds
root = ET.parse(os.path.join(vtkdir, pvds[0])).getroot()
files = [d.get("file") for d in root.iter("DataSet") if d.get("timestep") is not None and math.isclose(float(d.get("timestep")), float(time))]
assert files, "no dataset for time %s in the .pvd" % time
for f in files:
    assert os.path.exists(os.path.join(vtkdir, f)), "the .pvd names a missing file " + f

vtu = [f for f in files if f.endswith(".vtu")][0]
r = vtk.vtkXMLUnstructuredGridReader()
r.SetFileName(os.path.join(vtkdir, vtu))
r.Update()
grid = r.GetOutput()
assert grid.GetNumberOfPoints() == npoints, (grid.GetNumberOfPoints(), npoints)
assert grid.GetNumberOfCells() == ncells, (grid.GetNumberOfCells(), ncells)
conn = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
assert conn.min() >= 0 and conn.max() < npoints, "connectivity out of range"
for name in ("displacement",):
    a = vtk_to_numpy(grid.GetPointData().GetArray(name))
    assert a.shape[0] == npoints and all(map(math.isfinite, a.ravel())), name
for name in ("stress", "vonMises"):
    a = vtk_to_numpy(grid.GetCellData().GetArray(name))
    assert a.shape[0] == ncells and all(map(math.isfinite, a.ravel())), name

lines = open(os.path.join(case, time, "fractures", fracture + ".dat")).read().splitlines()
header = lines[0][1:].split()
rows = [l.split() for l in lines if not l.startswith("#")]
vtp = [f for f in files if f.endswith(".vtp") and os.path.basename(f).startswith(fracture + "_")][0]
p = vtk.vtkXMLPolyDataReader()
p.SetFileName(os.path.join(vtkdir, vtp))
p.Update()
poly = p.GetOutput()
assert poly.GetNumberOfPoints() == len(rows), (poly.GetNumberOfPoints(), len(rows))
# 16 columns, 17 with fractures that open (the opening after the residual), 3 more with a
# fluid pressure (pressure, sigmaNEffective and deltaCFS after it); nx ny tx ty slipX slipY
# last before the state
assert header[-1] == "state" and len(header) in (16, 17, 19, 20), header
assert header[-7:-1] == ["nx", "ny", "tx", "ty", "slipX", "slipY"], header
assert rows and all(len(r) == len(header) for r in rows), "expected %d columns per row" % len(header)
last = len(header) - 1
for i, row in enumerate(rows):
    assert all(math.isfinite(float(v)) for v in row[:last]), ("not finite", i, row)
names = ["slip", "sigmaN", "tau", "ST", "residual"] + (["opening"] if "opening" in header else [])
names += ["pressure", "sigmaNEffective", "deltaCFS"] if "pressure" in header else []
columns = {name: (header.index(name), 0) for name in names}
# The frame: point arrays of 3 components (z = 0) against the columns nx ny, tx ty.
columns.update({"normal": (header.index("nx"), 3), "tangent": (header.index("tx"), 3)})
for name, (col, components) in columns.items():
    array = poly.GetPointData().GetArray(name)
    assert array is not None, "no point array " + name
    a = vtk_to_numpy(array)
    assert all(map(math.isfinite, a.ravel())), "a value of %s is not finite" % name
    for i, row in enumerate(rows):
        for k in range(max(components, 1)):
            got = a[i] if components == 0 else a[i][k]
            want = 0.0 if k == 2 else float(row[col + k])
            assert math.isclose(got, want, rel_tol=1e-6, abs_tol=1e-12 * (1 + abs(want))), (name, i, got, want)
codes = {"stick": 0, "slip": 1, "open": 2, "tip": 3}
state = vtk_to_numpy(poly.GetPointData().GetArray("state"))
assert [int(s) for s in state] == [codes[row[last]] for row in rows], "state differs"
print("PASS: %s and %s match the tables (%d points, %d cells, %d fracture nodes, %d tips%s)" % (
    vtu, vtp, npoints, ncells, len(rows), sum(r[last] == "tip" for r in rows),
    (", opening" if "opening" in header else "") + (", pressure" if "pressure" in header else "")))
