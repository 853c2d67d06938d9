#!/usr/bin/env python3
"""Slip errors where two 3D fault surfaces cross, against the finest run (networkConvergence3d.sh).

Arguments: h=<folder with main.dat and crossing.dat>, coarsest first, the reference last.
Per fault, the reference's slip vector (slipX slipY slipZ) is interpolated linearly (a
Delaunay triangulation of its nodes in the fault's plane) at each coarser run's nodes; the
error is the root mean square of the difference over the nodes of a region, relative to the
reference's largest slip. Regions, all with y in [0.3, 0.7] (0.1 or more from the tip lines
at y = 0.2, 0.8): "curve", the nodes on the intersection (x = 0.45, z = 0.5); "near", nodes
within 0.1 of it; "far", nodes 0.15 or more from it ('crossing' is 0.25 wide on each side, so
its far nodes are within 0.1 of its tip lines). The observed order between successive sizes
is log(e_i / e_i+1) / log(h_i / h_i+1) (the reference's own error adds to both).
"""
import math
import sys

import numpy as np
from scipy.interpolate import LinearNDInterpolator

LINE_POINT = np.array([0.45, 0.0, 0.5])
LINE_DIR = np.array([0.0, 1.0, 0.0])


def read(path):
    cols = None
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("# x "):
                cols = line[2:].split()
            elif line.strip() and not line.startswith("#"):
                rows.append([float(v) for v in line.split()[:-1]])
    if cols is None or len(rows) < 3:
        sys.exit(f"{path}: not a 3D fracture table")
    a = np.array(rows)
    col = {c: i for i, c in enumerate(cols[:-1])}
    x = a[:, [col["x"], col["y"], col["z"]]]
    n = a[:, [col["nx"], col["ny"], col["nz"]]]
    s = a[:, [col["slipX"], col["slipY"], col["slipZ"]]]
    return x, n, s


def distance(x):
    d = x - LINE_POINT
    return np.linalg.norm(d - np.outer(d @ LINE_DIR, LINE_DIR), axis=1)


def main():
    runs = []
    for arg in sys.argv[1:]:
        h, _, folder = arg.partition("=")
        runs.append((float(h), folder))
    if len(runs) < 3:
        sys.exit("usage: networkConvergence3d.py h=folder ... (coarsest first, reference last)")
    href, fref = runs[-1]
    print(f"\nSlip error against h = {href} m (RMS over the region's nodes / largest slip):\n")
    print("| fault | region | " + " | ".join(f"h = {h}" for h, _ in runs[:-1]) +
          " | observed orders |")
    print("|---" * (len(runs) + 2) + "|")
    for fault in ("main", "crossing"):
        xr, nr, sr = read(f"{fref}/{fault}.dat")
        normal = nr[0]
        e1 = LINE_DIR
        e2 = np.cross(normal, e1)
        interp = LinearNDInterpolator(np.c_[xr @ e1, xr @ e2], sr)
        scale = np.max(np.linalg.norm(sr, axis=1))
        errors = {"curve": [], "near": [], "far": []}
        for h, folder in runs[:-1]:
            x, n, s = read(f"{folder}/{fault}.dat")
            # The splitters of two meshes may take opposite sides as Omega+: the jump's sign
            # follows n.
            s = s * np.sign(n @ normal)[:, None]
            ref = interp(np.c_[x @ e1, x @ e2])
            inside = (x[:, 1] >= 0.3 - 1e-9) & (x[:, 1] <= 0.7 + 1e-9) & ~np.isnan(ref[:, 0])
            d = distance(x)
            diff = np.linalg.norm(s - ref, axis=1) / scale
            for region, mask in (("curve", d < 1e-9), ("near", d <= 0.1), ("far", d >= 0.15)):
                m = inside & mask
                if m.sum() == 0:
                    sys.exit(f"{folder}/{fault}.dat: no nodes in region {region}")
                errors[region].append(math.sqrt(np.mean(diff[m] ** 2)))
        for region, e in errors.items():
            hs = [h for h, _ in runs[:-1]]
            orders = [math.log(e[i] / e[i + 1]) / math.log(hs[i] / hs[i + 1])
                      for i in range(len(e) - 1)]
            print(f"| {fault} | {region} | " + " | ".join(f"{v:.2e}" for v in e) + " | " +
                  ", ".join(f"{o:.2f}" for o in orders) + " |")


if __name__ == "__main__":
    main()
