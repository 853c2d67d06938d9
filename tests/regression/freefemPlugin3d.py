#!/usr/bin/python3
"""The checks of tests/regression/freefemPlugin.sh in 3D: freefemPlugin3d.edp's outputs in the
plug-in's folder against frictionSolver's last time folder in the command line's folder.

Usage: freefemPlugin3d.py PLUGIN_CASE CLI_CASE ORDER LAST_TIME FRACTURE
"""
import re
import sys

import numpy as np

ff, cli, order, last, fracture = sys.argv[1:]
COLUMNS = 20  # x y z nx ny nz slip1 slip2 slipX slipY slipZ slipMagnitude ... residual

got = np.loadtxt(ff + "/freefemTable.dat", ndmin=2)
same = np.loadtxt("%s/%s/fractures/%s.dat" % (cli, last, fracture), comments="#",
                  usecols=range(COLUMNS), ndmin=2)
assert len(got) > 0 and got.shape[0] == same.shape[0], "row counts differ"
assert got.shape[1] == COLUMNS + 1, "the table has %d columns, expected %d and the state" % (
    got.shape[1], COLUMNS)
scale = np.max(np.abs(same[:, 11]))
assert scale > 0.1, "the fault slips (about 1 m at the end): got %g" % scale
for j in range(COLUMNS):
    a, b = got[:, j], same[:, j]
    assert np.array_equal(np.isnan(a), np.isnan(b)), "column %d: nan" % j
    m = ~np.isnan(a)
    tol = 1e-12 * max(np.max(np.abs(b[m])), 1e-300)
    assert np.max(np.abs(a[m] - b[m])) <= tol, "column %d differs" % j

u = np.loadtxt(ff + "/freefemDisplacement.dat", ndmin=2)
text = open("%s/%s/D" % (cli, last)).read()
body = text[text.index("internalField"):]
n = int(re.search(r"List<vector>\s+(\d+)", body).group(1))
opener = body.index("(", body.index(str(n)))  # the list's own parenthesis
D = np.array(re.findall(r"\(\s*([^\s()]+)\s+([^\s()]+)\s+([^\s()]+)\s*\)", body[opener + 1:])[:n], dtype=float)
assert n > 0 and u.shape == D.shape, "vertex counts differ"
du = np.max(np.abs(u - D)) / np.max(np.abs(D))

log = open(ff + "/log.FreeFem++").read()
m = re.search(r"^loads: (.*)$", log, re.M)
assert m, "the script printed no 'loads:' line"
loads = [float(x) for x in m.group(1).split()]
print("3D P%s: %d fault nodes, largest slip %.3f m; table and displacement against "
      "frictionSolver %.1e; |u - u_D| integrated over north, south, west, bottom at the "
      "fespace's nodes: %s" % (order, len(got), scale, du, " ".join("%.1e" % x for x in loads)))
assert du <= 1e-12, "3D P%s: the displacement differs by %g" % (order, du)
# Integrals over faces of 1e6 m² of |u - u_D| with |u| ~ 1 m: round-off is ~1e-10; a value on
# the wrong node of FreeFEM's P2 numbering gives ~1e3.
assert max(loads) <= 1e-6, "3D P%s: the displacement misses the Dirichlet values" % order
