#!/usr/bin/python3
"""Compares a penny-crack result with the analytic slip (docs/method.md, three dimensions).

A disc-shaped fault of radius a in an infinite body under a uniform remote stress sigma0
slips over its whole area when dtau = |tau_inf| - (c - mu_f sigma_n_inf) > 0, along the
resolved shear, with

    |slip|(r) = 8 (1 - nu) dtau / (pi (2 - nu) G) * sqrt(a^2 - r^2),  G = E / (2 (1 + nu))

(Eshelby 1957; Segall 2010, eq. 4.74). Reads the case's constant/mechanicalProperties,
constant/fractureProperties and constant/effects (the initialStress entry), the 3D fracture
table <time>/fractures/<name>.dat and the fault surface VTK/fractures/<name>_<time>.vtp (its
triangles give the integration weights; the .vtp's points are the table's rows, in order;
P2 triangles, written as four triangles at their edge midpoints, are put back together).
The disc's centre and radius come from the tip nodes (the rim), its normal from the table.

Prints, as "key value" lines:
  * the relative L2(Gamma) error of |slip|, integrated over the fault triangles with the
    nodal values interpolated (P1 linear, P2 quadratic) and a 16 x 7-point rule per
    triangle, and its lumped (nodal-quadrature) variant;
  * the amplitude ratio (least-squares factor of computed over analytic |slip| at the
    nodes, lumped weights): the finite-size factor of the cube once the mesh is fine;
  * at slipping nodes with r < inner * a: the largest angle between the slip and the
    remote resolved shear (the slip is opposite to tau on Omega+, i.e. along -tau_inf with
    the table's normal), the largest angle between the slip and -tau (the friction law's
    direction), the largest | |tau| - (c - mu_f sigma_n) | / (c - mu_f sigma_n), the
    largest |sigma_n - sigma_n_inf| / |sigma_n_inf|;
  * the number of nodes in each state.

Options --maxError, --maxAngle, --maxLaw turn these into checks: exit 3 when one fails (or
when the set of nodes it looks at is empty). Exit 1 on bad input (a 2D table, a missing
file or key), 2 on a bad command line.

Usage: pennyError.py [-case DIR] [-time T] [-fracture NAME] [-inner 0.9]
                     [--maxError E] [--maxAngle DEG] [--maxLaw R]
"""

import argparse
import math
import os
import re
import sys

import numpy as np


class InputError(Exception):
    pass


# --- OpenFOAM-style dictionaries (the subset the case files use) -------------------------

def parseDict(path):
    """Returns the dictionary as nested dicts; a value is its list of tokens."""
    try:
        text = open(path).read()
    except OSError as e:
        raise InputError(f"{path}: cannot read ({e.strerror})")
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    tokens = re.findall(r'"[^"]*"|[{}();]|[^\s{}();"]+', text)
    pos = 0

    def block(end):
        nonlocal pos
        d = {}
        while pos < len(tokens):
            t = tokens[pos]
            if t == end:
                pos += 1
                return d
            if t in "{}();":
                raise InputError(f"{path}: unexpected '{t}'")
            key = t
            pos += 1
            if pos < len(tokens) and tokens[pos] == "{":
                pos += 1
                d[key] = block("}")
                continue
            value, depth = [], 0
            while pos < len(tokens) and not (tokens[pos] == ";" and depth == 0):
                depth += {"(": 1, ")": -1}.get(tokens[pos], 0)
                value.append(tokens[pos])
                pos += 1
            if pos == len(tokens):
                raise InputError(f"{path}: key '{key}': missing ';'")
            pos += 1
            d[key] = value
        if end != "":
            raise InputError(f"{path}: missing '{end}'")
        return d

    return block("")


def number(path, key, value):
    if len(value) != 1:
        raise InputError(f"{path}: key '{key}': expected one number")
    try:
        return float(value[0])
    except ValueError:
        raise InputError(f"{path}: key '{key}': '{value[0]}' is not a number")


def numberList(path, key, value, n):
    inner = [t for t in value if t not in "()"]
    if len(inner) != n or value[0] != "(" or value[-1] != ")":
        raise InputError(f"{path}: key '{key}': expected ({n} numbers)")
    return [number(path, key, [t]) for t in inner]


def caseParameters(case, fracture):
    p = {}
    path = os.path.join(case, "constant/mechanicalProperties")
    d = parseDict(path)
    if "E" in d and "nu" in d:
        E, nu = number(path, "E", d["E"]), number(path, "nu", d["nu"])
        p["G"], p["nu"] = E / (2 * (1 + nu)), nu
    elif "lambda" in d and "mu" in d:
        lam, mu = number(path, "lambda", d["lambda"]), number(path, "mu", d["mu"])
        p["G"], p["nu"] = mu, lam / (2 * (lam + mu))
    else:
        raise InputError(f"{path}: expected the keys E and nu (or lambda and mu)")

    path = os.path.join(case, "constant/fractureProperties")
    d = parseDict(path)
    if fracture not in d or not isinstance(d[fracture], dict):
        raise InputError(f"{path}: no sub-dictionary '{fracture}'")
    f = d[fracture]
    law = f.get("law", ["?"])[0]
    if law not in ("coulomb", "coulombCohesion"):
        raise InputError(f"{path}: {fracture}/law is '{law}': the penny formula here needs "
                         "coulomb or coulombCohesion")
    p["muF"] = number(path, "frictionCoefficient", f.get("frictionCoefficient", []))
    p["c"] = number(path, "cohesion", f["cohesion"]) if law == "coulombCohesion" else 0.0

    path = os.path.join(case, "constant/effects")
    d = parseDict(path) if os.path.exists(path) else {}
    stresses = []
    for name, e in d.items():
        if name == "FoamFile" or not isinstance(e, dict) or e.get("active", ["yes"])[0] == "no":
            continue
        kind = e.get("type", ["?"])[0]
        if kind == "initialStress":
            if "gradient" in e:
                raise InputError(f"{path}: {name}/gradient: the penny formula needs a uniform "
                                 "remote stress")
            stresses.append(numberList(path, name + "/stress", e.get("stress", []), 6))
        else:
            raise InputError(f"{path}: effect '{name}' ({kind}): the penny formula has only a "
                             "uniform remote stress")
    if not stresses:
        raise InputError(f"{path}: no active initialStress entry (the remote stress)")
    s = np.sum(stresses, axis=0)  # xx yy zz xy yz xz
    p["sigma0"] = np.array([[s[0], s[3], s[5]], [s[3], s[1], s[4]], [s[5], s[4], s[2]]])
    return p


# --- the 3D fracture table and the fault surface ------------------------------------------

COLUMNS3D = ("x y z nx ny nz slip1 slip2 slipX slipY slipZ slipMagnitude slipIncrement1 "
             "slipIncrement2 sigmaN tau1 tau2 tauMagnitude ST residual state").split()


def latestTime(case, fracture):
    times = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if t > 0 and os.path.isfile(os.path.join(case, d, "fractures", fracture + ".dat")):
            times.append((t, d))
    if not times:
        raise InputError(f"{case}: no time folder with fractures/{fracture}.dat (run the case)")
    return max(times)[1]


def readTable(path, columns=COLUMNS3D):
    """A 3D fracture table with the given columns (a unilateral fracture's have 'opening'
    before 'state', a fluid pressure's 'pressure sigmaNEffective ...'): its columns by name, the
    status line and the frame line."""
    try:
        lines = open(path).read().splitlines()
    except OSError as e:
        raise InputError(f"{path}: cannot read ({e.strerror})")
    if not lines or not lines[0].startswith("#"):
        raise InputError(f"{path}:1: expected the column header")
    header = lines[0][1:].split()
    # A fluid pressure adds 'pressure sigmaNEffective deltaCFS slipStrike slipDip tauStrike
    # tauDip' before the state (README, "Fluid pressure"): the same table with more columns.
    if header == list(columns[:-1]) + ["pressure", "sigmaNEffective", "deltaCFS", "slipStrike",
                                       "slipDip", "tauStrike", "tauDip", "state"]:
        columns = header
    if header != list(columns):
        if header[:3] == ["s", "x", "y"]:
            raise InputError(f"{path}: a 2D fracture table (columns {' '.join(header)}); "
                             "pennyError.py compares 3D results (columns x y z nx ny nz ...)")
        raise InputError(f"{path}:1: expected the 3D columns '# {' '.join(columns)}'")
    status = lines[1] if len(lines) > 1 else ""
    if not status.startswith("# status"):
        raise InputError(f"{path}:2: expected the '# status' line")
    frame = None
    rows = []
    for i, line in enumerate(lines[2:], start=3):
        if line.startswith("# frame"):
            frame = line
            continue
        if not line.strip() or line.startswith("#"):
            continue
        f = line.split()
        if len(f) != len(columns):
            raise InputError(f"{path}:{i}: expected {len(columns)} columns, found {len(f)}")
        try:
            rows.append([float(v) for v in f[:-1]] + [f[-1]])
        except ValueError:
            raise InputError(f"{path}:{i}: a value is not a number")
    if not rows:
        raise InputError(f"{path}: no rows")
    cols = {c: np.array([r[k] for r in rows], dtype=float if c != "state" else object)
            for k, c in enumerate(columns)}
    bad = set(cols["state"]) - {"stick", "slip", "open", "tip"}
    if bad:
        raise InputError(f"{path}: unknown state(s) {sorted(bad)}")
    return cols, status, frame


def flatDisc(t, tablePath, vtpPath):
    """The fault of table t (its surface in vtpPath) as a flat disc: node positions xyz, the
    normal n, the triangles and their order, the rim's nodes (tip nodes that are triangle
    vertices: a P2 rim edge's midpoint lies inside), the centre, the nodes' offsets d from it,
    their in-plane radii r and the radius a. InputError where the fault is not a flat disc."""
    xyz = np.stack([t["x"], t["y"], t["z"]], axis=1)
    normals = np.stack([t["nx"], t["ny"], t["nz"]], axis=1)
    n = normals.mean(axis=0)
    n /= np.linalg.norm(n)
    if np.abs(normals - n).max() > 1e-8:
        raise InputError(f"{tablePath}: the normals differ from node to node: the penny "
                         "formula is for a flat disc")
    tri = readVtp(vtpPath, xyz)
    order = 1 if tri.shape[1] == 3 else 2
    tips = np.zeros(len(xyz), dtype=bool)
    tips[np.unique(tri[:, :3])] = True
    tips &= t["state"] == "tip"
    if tips.sum() < 3:
        raise InputError(f"{tablePath}: {tips.sum()} tip nodes: cannot find the disc's rim")
    centre = xyz[tips].mean(axis=0)
    d = xyz - centre
    r = np.linalg.norm(d - np.outer(d @ n, n), axis=1)
    a = r[tips].mean()
    if np.abs(d @ n).max() > 1e-8 * a or np.abs(r[tips] - a).max() > 1e-6 * a:
        raise InputError(f"{tablePath}: the fault is not a disc (its tip nodes are not on one "
                         "circle in the plane of the nodes)")
    return xyz, n, tri, order, tips, centre, d, r, a


def readVtp(path, xyz):
    """Fault triangles as row indices (k, 3) for P1 or (k, 6) for P2."""
    if not os.path.isfile(path):
        raise InputError(f"{path}: not found (the fault surface; run with writeVTK yes)")
    try:
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
    except ImportError:
        raise InputError("VTK for python not found (Debian package python3-vtk9; "
                         "run with /usr/bin/python3)")
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    poly = r.GetOutput()
    if poly.GetNumberOfPoints() != len(xyz):
        raise InputError(f"{path}: {poly.GetNumberOfPoints()} points, the table has "
                         f"{len(xyz)} rows")
    pts = vtk_to_numpy(poly.GetPoints().GetData())
    scale = max(np.abs(xyz).max(), 1.0)
    if np.abs(pts - xyz).max() > 1e-6 * scale:
        raise InputError(f"{path}: its points are not the table's rows (in row order)")
    cells, kinds = [], set()
    for c in range(poly.GetNumberOfCells()):
        cell = poly.GetCell(c)
        kinds.add(cell.GetCellType())
        cells.append([cell.GetPointId(k) for k in range(cell.GetNumberOfPoints())])
    if not cells:
        raise InputError(f"{path}: no cells")
    if kinds != {vtk.VTK_TRIANGLE}:
        raise InputError(f"{path}: expected triangles (VTK_TRIANGLE, 5) only, found cell "
                         f"types {sorted(kinds)}")
    tri = np.array(cells)
    # P2: a .vtp holds linear cells only, so frictionSolver writes each six-node triangle as
    # four triangles at its edge midpoints, (v0 m01 m20) (m01 v1 m12) (m20 m12 v2)
    # (m01 m12 m20); put them back together, so that the slip is interpolated quadratically.
    if len(tri) % 4 == 0:
        c0, c1, c2, c3 = tri[0::4], tri[1::4], tri[2::4], tri[3::4]
        if (np.array_equal(c0[:, 1], c1[:, 0]) and np.array_equal(c0[:, 1], c3[:, 0]) and
                np.array_equal(c1[:, 2], c2[:, 1]) and np.array_equal(c1[:, 2], c3[:, 1]) and
                np.array_equal(c0[:, 2], c2[:, 0]) and np.array_equal(c0[:, 2], c3[:, 2])):
            six = np.stack([c0[:, 0], c1[:, 1], c2[:, 2], c0[:, 1], c1[:, 2], c0[:, 2]], axis=1)
            mids = (pts[six[:, [0, 1, 2]]] + pts[six[:, [1, 2, 0]]]) / 2
            if np.abs(mids - pts[six[:, 3:]]).max() <= 1e-6 * scale:
                return six
    return tri


# --- quadrature -----------------------------------------------------------------------------

def referenceRule(levels=2):
    """Barycentric points and weights (sum 1) on the reference triangle: each of the 4^levels
    sub-triangles gets the 7-point degree-5 rule (the exact slip is not smooth at the rim)."""
    a1, b1 = 0.059715871789770, 0.470142064105115
    a2, b2 = 0.797426985353087, 0.101286507323456
    bary = [(1 / 3, 1 / 3, 1 / 3)]
    w = [0.225]
    for (a, b, wk) in ((a1, b1, 0.132394152788506), (a2, b2, 0.125939180544827)):
        bary += [(a, b, b), (b, a, b), (b, b, a)]
        w += [wk] * 3
    bary, w = np.array(bary), np.array(w)
    tris = [np.eye(3)]  # sub-triangles as barycentric vertex rows
    for _ in range(levels):
        new = []
        for t in tris:
            m01, m12, m20 = (t[0] + t[1]) / 2, (t[1] + t[2]) / 2, (t[2] + t[0]) / 2
            new += [np.array(v) for v in ((t[0], m01, m20), (m01, t[1], m12),
                                          (m20, m12, t[2]), (m01, m12, m20))]
        tris = new
    P = np.concatenate([bary @ t for t in tris])
    W = np.concatenate([w / len(tris)] * len(tris))
    return P, W


def shape(P, order):
    l0, l1, l2 = P[:, 0], P[:, 1], P[:, 2]
    if order == 1:
        return P
    # vertices v0 v1 v2, then mid01 mid12 mid20 (VTK_QUADRATIC_TRIANGLE)
    return np.stack([l0 * (2 * l0 - 1), l1 * (2 * l1 - 1), l2 * (2 * l2 - 1),
                     4 * l0 * l1, 4 * l1 * l2, 4 * l2 * l0], axis=1)


# --- the comparison -------------------------------------------------------------------------

def angleDeg(u, v):
    """Angles between the rows of u and v (n x 2 or n x 3) [deg]; atan2 keeps small angles
    accurate (arccos of the cosine loses them below ~1e-8 rad)."""
    if u.shape[1] == 2:
        u, v = np.pad(u, ((0, 0), (0, 1))), np.pad(v, ((0, 0), (0, 1)))
    return np.degrees(np.arctan2(np.linalg.norm(np.cross(u, v), axis=1),
                                 np.einsum("ij,ij->i", u, v)))


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("-case", default=".")
    ap.add_argument("-time", default=None, help="time folder (default: the latest)")
    ap.add_argument("-fracture", default="fault")
    ap.add_argument("-inner", type=float, default=0.9,
                    help="pointwise checks at r < inner*a (default 0.9)")
    ap.add_argument("--maxError", type=float, help="check: relative L2 error <= this")
    ap.add_argument("--maxAngle", type=float, help="check: both angles <= this [deg]")
    ap.add_argument("--maxLaw", type=float, help="check: the friction-law deviation <= this")
    try:
        args = ap.parse_args(argv)
    except SystemExit as e:
        return 0 if e.code == 0 else 2

    case = args.case
    time = args.time or latestTime(case, args.fracture)
    tablePath = os.path.join(case, time, "fractures", args.fracture + ".dat")
    t, status, frame = readTable(tablePath)
    p = caseParameters(case, args.fracture)
    slip = np.stack([t["slipX"], t["slipY"], t["slipZ"]], axis=1)
    state = t["state"]
    vtpPath = os.path.join(case, "VTK", "fractures", f"{args.fracture}_{time}.vtp")
    xyz, n, tri, order, tips, centre, d, r, a = flatDisc(t, tablePath, vtpPath)
    inPlane = d - np.outer(d @ n, n)

    # The remote state resolved on the fault, with the table's normal (from Omega+ to Omega-):
    # tau_inf is the remote traction on Omega+; the slip u+ - u- goes along -tau_inf.
    trac = p["sigma0"] @ n
    sigmaNInf = trac @ n
    tauInf = trac - sigmaNInf * n
    bound = p["c"] - p["muF"] * sigmaNInf
    dtau = np.linalg.norm(tauInf) - bound
    if dtau <= 0:
        raise InputError(f"{case}: dtau = |tau_inf| - (c - mu_f sigma_n_inf) = {dtau:g} Pa "
                         "<= 0: the remote stress does not make the disc slip")
    G, nu = p["G"], p["nu"]
    amp = 8 * (1 - nu) * dtau / (math.pi * (2 - nu) * G)
    exact = lambda rr: amp * np.sqrt(np.maximum(a * a - rr * rr, 0.0))

    # Relative L2(Gamma) error of |slip|.
    v0, v1, v2 = xyz[tri[:, 0]], xyz[tri[:, 1]], xyz[tri[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(v1 - v0, v2 - v0), axis=1)
    P, W = referenceRule()
    N = shape(P, order)                      # (q, nodes per triangle)
    mag = t["slipMagnitude"]
    num = N @ mag[tri].T                     # (q, triangles): the interpolated |slip|
    X = np.einsum("qk,tkd->qtd", P, np.stack([v0, v1, v2], axis=1))
    dq = X - centre
    rq = np.linalg.norm(dq - np.einsum("qt,d->qtd", dq @ n, n), axis=2)
    ex = exact(rq)
    wq = np.outer(W, area)
    err = math.sqrt((wq * (num - ex) ** 2).sum() / (wq * ex ** 2).sum())
    # Lumped: P1 A/3 per vertex; P2 P1-iso-P2 weights A/12 per vertex, A/4 per mid-edge node.
    wn = np.zeros(len(xyz))
    for k in range(tri.shape[1]):
        np.add.at(wn, tri[:, k], area * ((1 / 3) if order == 1 else (1 / 12 if k < 3 else 1 / 4)))
    exn = np.where(tips, 0.0, exact(r))   # the rim's nodes lie on the circle to rounding
    errLumped = math.sqrt((wn * (mag - exn) ** 2).sum() / (wn * exn ** 2).sum())
    # Nodal, so that the interpolation error of sqrt(a^2 - r^2) does not bias it.
    ratio = (wn * mag * exn).sum() / (wn * exn ** 2).sum()

    # Pointwise checks away from the rim.
    sel = (state == "slip") & (r < args.inner * a)
    angleRemote = angleDeg(slip[sel], -np.tile(tauInf, (sel.sum(), 1))) if sel.any() else []
    s12 = np.stack([t["slip1"], t["slip2"]], axis=1)[sel]
    t12 = np.stack([t["tau1"], t["tau2"]], axis=1)[sel]
    angleTau = angleDeg(s12, -t12) if sel.any() else []
    lawBound = p["c"] - p["muF"] * t["sigmaN"][sel]
    law = np.abs(t["tauMagnitude"][sel] - lawBound) / lawBound if sel.any() else []
    dSigmaN = np.abs(t["sigmaN"][sel] - sigmaNInf) / abs(sigmaNInf) if sel.any() else []
    # Consistency of the table: slipX.. = slip1 t1 + slip2 t2 for the written frame.
    frameErr = None
    if frame and "per node" not in frame:
        v = " ".join(re.findall(r"\(([^)]*)\)", frame)).split()
        if len(v) == 9:
            v = [float(x) for x in v]
            t1, t2 = np.array(v[3:6]), np.array(v[6:9])
            rec = np.outer(t["slip1"], t1) + np.outer(t["slip2"], t2)
            frameErr = np.abs(rec - slip).max() / max(np.abs(slip).max(), 1e-300)

    mx = lambda x: max(x) if len(x) else float("nan")
    out = [
        ("table", tablePath), ("surface", vtpPath), ("status", status[1:].strip()),
        ("elements", f"P{order} triangles {len(tri)}, nodes {len(xyz)}"),
        ("disc", f"centre ({' '.join(f'{c:.6g}' for c in centre)}) radius {a:.9g} m "
                 f"normal ({' '.join(f'{c:.6g}' for c in n)})"),
        ("G nu muF c", f"{G:.6g} {nu:.6g} {p['muF']:.6g} {p['c']:.6g}"),
        ("remote", f"sigmaN {sigmaNInf:.6g} Pa, |tau| {np.linalg.norm(tauInf):.6g} Pa, "
                   f"dtau {dtau:.6g} Pa"),
        ("centreSlipExact", f"{amp * a:.6e} m"),
        ("centreSlipNearest", f"{mag[np.argmin(r)]:.6e} m at r = {r.min():.3g} m"),
        ("relL2Error", f"{err:.6e}"),
        ("relL2ErrorLumped", f"{errLumped:.6e}"),
        ("amplitudeRatio", f"{ratio:.6f}"),
        ("innerSlipNodes", f"{sel.sum()} (state slip, r < {args.inner:g} a)"),
        ("maxAngleSlipRemoteShear", f"{mx(angleRemote):.6e} deg"),
        ("maxAngleSlipMinusTau", f"{mx(angleTau):.6e} deg"),
        ("maxLawDeviation", f"{mx(law):.6e}"),
        ("maxSigmaNChange", f"{mx(dSigmaN):.6e}"),
        ("states", " ".join(f"{s} {int((state == s).sum())}"
                            for s in ("stick", "slip", "open", "tip"))),
    ]
    if frameErr is not None:
        out.append(("frameConsistency", f"{frameErr:.3e}"))
    width = max(len(k) for k, _ in out)
    for k, v in out:
        print(f"{k:<{width}}  {v}")

    failed = []
    if args.maxError is not None and not err <= args.maxError:
        failed.append(f"relL2Error {err:.3e} > {args.maxError:g}")
    for name, lim, vals in (("angle", args.maxAngle, list(angleRemote) + list(angleTau)),
                            ("law", args.maxLaw, list(law))):
        if lim is None:
            continue
        if not len(vals):
            failed.append(f"{name}: no slipping nodes with r < {args.inner:g} a to check")
        elif not max(vals) <= lim:
            failed.append(f"{name} {max(vals):.3e} > {lim:g}")
    for f in failed:
        print("FAILED:", f)
    return 3 if failed else 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except InputError as e:
        print("pennyError.py: error:", e, file=sys.stderr)
        sys.exit(1)
