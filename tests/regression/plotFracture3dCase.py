#!/usr/bin/python3
"""Writes a synthetic 3D case for the plotFracture3d regression test: the fracture table of a
fault surface exactly as SPEC'd for frictionSolver's 3D output (README.md, "frictionSolver":
'# x y z nx ny nz slip1 slip2 ...', '# status ...', '# frame ...', one row per node) in
<case>/<time>/fractures/fault.dat, and constant/fractureProperties (law coulomb, mu_f 0.6).

Usage: plotFracture3dCase.py CASE SHAPE
  disc       a flat penny of radius A = 0.5 m centred at C, normal N (inclined), nodes on
             rings (spacing A/20), the rim nodes tips; the penny-crack slip magnitude
             |slip|(r) = K sqrt(A^2 - r^2) (docs/method.md) along the direction at 40 deg from
             t1, at times 0.5 (half the slip) and 1
  cap        the same nodes lifted onto a sphere of radius 2 m (a curved fault: per-node
             normals, '# frame per node'), the same slip as a function of the radius in the
             plane of the disc, at time 1
  rectangle  a flat 2 m x 1 m rectangle (21 x 11 nodes, the border tips), time 1
  locked     the rectangle without slip (every slip column 0), time 1
  patch      the disc's nodes with slip only on a patch off the centre: the penny-crack
             slip of radius A/2 centred on the node PATCH (in the map plane), time 1
  horizontal the disc with the normal NH = -z (a horizontal fault, n pointing down), time 1
  vertical   the disc with the normal NV (a vertical fault), time 1
sigmaN and tauMagnitude are linear in x y z of the point of the disc's plane under the node
(the node itself on the disc and the rectangle), so linear in the map coordinates, and a
linear interpolation reproduces them to round-off; ST = tauMagnitude / -sigmaN.
Prints nothing; the test recomputes the analytic values from the constants below.
"""
import os
import sys

import numpy as np

A = 0.5
C = np.array([1.0, 2.0, 3.0])
N = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])
NU, G, DTAU = 0.25, 1e9, 1e6
K = 8 * (1 - NU) * DTAU / (np.pi * (2 - NU) * G)  # [m/m]: |slip| = K sqrt(A^2 - r^2)
ANGLE = np.radians(40.0)
RINGS = 20
SPHERE = 2.0


def tangentBasis(n):
    axis = int(np.argmin(np.abs(n)))
    e = np.eye(3)[axis]
    t1 = e - e.dot(n) * n
    t1 /= np.linalg.norm(t1)
    return t1, np.cross(n, t1)


T1, T2 = tangentBasis(N)
NH = np.array([0.0, 0.0, -1.0])
NV = np.array([0.6, 0.8, 0.0])
PATCH = (0.25 * np.cos(np.pi / 3), 0.25 * np.sin(np.pi / 3))  # a node of ring 10


def shapeFrame(shape):
    """The flat shapes' normal and tangents (the cap: the disc's, before the lift)."""
    n = {"horizontal": NH, "vertical": NV}.get(shape, N)
    return (n, *tangentBasis(n))


def sigmaN(p):
    return -1e7 + 2e6 * (p[0] - C[0]) + 1e6 * (p[2] - C[2])


def tauMagnitude(p):
    return 4e6 + 1e6 * (p[1] - C[1])


def pressure(p):
    """A fluid pressure for the test's tables with pressure columns (not written here)."""
    return 2e7 + 3e6 * (p[0] - C[0]) - 2e6 * (p[1] - C[1]) + 1e6 * (p[2] - C[2])


def discPoints():
    pts = [(0.0, 0.0, False)]
    for k in range(1, RINGS + 1):
        r = A * k / RINGS
        for j in range(6 * k):
            a = 2 * np.pi * j / (6 * k)
            pts.append((r * np.cos(a), r * np.sin(a), k == RINGS))
    return pts


def rows(shape, scale):
    out = []
    N, T1, T2 = shapeFrame(shape)  # noqa: N806 (the disc's N, T1, T2 but for two shapes)
    if shape == "locked":
        shape, scale = "rectangle", 0.0
    if shape == "rectangle":
        grid = [(u, v, abs(u) > 0.999 or abs(v) > 0.499)
                for v in np.linspace(-0.5, 0.5, 11) for u in np.linspace(-1.0, 1.0, 21)]
    else:
        grid = discPoints()
    for u, v, tip in grid:
        if shape == "rectangle":
            mag = 0.0 if tip else K * A * np.sqrt((1 - u * u) * (1 - 4 * v * v))
        elif shape == "patch":
            r2 = (u - PATCH[0]) ** 2 + (v - PATCH[1]) ** 2
            mag = 0.0 if tip else K * np.sqrt(max(A * A / 4 - r2, 0.0))
        else:
            mag = 0.0 if tip else K * np.sqrt(A * A - u * u - v * v)
        mag *= scale
        p = C + u * T1 + v * T2
        n = N
        if shape == "cap":
            w = SPHERE - np.sqrt(SPHERE ** 2 - u * u - v * v)
            p = p + w * N
            n = C + SPHERE * N - p
            n /= np.linalg.norm(n)
        t1, t2 = tangentBasis(n)
        # The slip direction is fixed in the plane of (T1, T2); on the cap it is that vector
        # made tangent to the sphere (along N, so that its projection on the map plane keeps
        # the disc's direction) and normalised (so that |slip| is the penny's).
        d = np.cos(ANGLE) * T1 + np.sin(ANGLE) * T2
        if shape == "cap":
            d = d - (d.dot(n) / n.dot(N)) * N
            d /= np.linalg.norm(d)
        slipXYZ = mag * d
        s1, s2 = slipXYZ.dot(t1), slipXYZ.dot(t2)
        slipXYZ = s1 * t1 + s2 * t2
        if tip:
            traction = ["nan"] * 6
            state = "tip"
        else:
            flat = C + u * T1 + v * T2  # on the cap too: linear in the map coordinates
            sn, tm = sigmaN(flat), tauMagnitude(flat)
            tau = -tm * np.array([s1, s2]) / np.hypot(s1, s2) if mag > 0 else [tm, 0.0]
            traction = [sn, tau[0], tau[1], tm, tm / -sn, 1e-12]
            state = "slip" if np.hypot(u, v) < 0.8 * A else "stick"
        values = [*p, *n, s1, s2, *slipXYZ, np.linalg.norm(slipXYZ), 0.1 * s1, 0.1 * s2,
                  *traction]
        out.append(" ".join(v if isinstance(v, str) else f"{v:.17g}" for v in values)
                   + " " + state)
    return out


def write(case, shape, time, scale):
    N, T1, T2 = shapeFrame(shape)  # noqa: N806
    folder = os.path.join(case, time, "fractures")
    os.makedirs(folder, exist_ok=True)
    if shape == "cap":
        frame = ("# frame per node: n in columns nx ny nz, t1 = tangentBasis(n), t2 = n x t1 "
                 "(docs/method.md)")
    else:
        v = lambda x: "(" + " ".join(f"{c:.17g}" for c in x) + ")"  # noqa: E731
        frame = f"# frame n {v(N)} t1 {v(T1)} t2 {v(T2)}"
    with open(os.path.join(folder, "fault.dat"), "w") as f:
        f.write("# x y z nx ny nz slip1 slip2 slipX slipY slipZ slipMagnitude slipIncrement1 "
                "slipIncrement2 sigmaN tau1 tau2 tauMagnitude ST residual state\n")
        f.write("# status converged iterations 3 J 1e-30 relResidual 1e-16\n")
        f.write(frame + "\n")
        f.write("\n".join(rows(shape, scale)) + "\n")


def main(case, shape):
    os.makedirs(os.path.join(case, "constant"), exist_ok=True)
    with open(os.path.join(case, "constant", "fractureProperties"), "w") as f:
        f.write("fault\n{\n    law coulomb;\n    frictionCoefficient 0.6;\n}\n")
    if shape == "disc":
        write(case, shape, "0.5", 0.5)
    write(case, shape, "1", 1.0)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
