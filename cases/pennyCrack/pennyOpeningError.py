#!/usr/bin/python3
"""Compares the opening of a pressurised penny crack with Sneddon's (docs/method.md §10).

A disc-shaped crack of radius a in an infinite body, its faces loaded by a fluid pressure p
(the fracturePressure effect) under a uniform remote stress whose normal component on the
disc is sigma_n_inf (negative in compression; 0 without an initialStress effect), opens over
its whole area when the net pressure dp = p + sigma_n_inf is positive:

    g(r) = 8 (1 - nu^2) dp / (pi E) * sqrt(a^2 - r^2)

(Sneddon 1946), with sigma_n = -p and tau = 0 on the open faces. A remote shear does not
change g (on a flat crack in an isotropic body the normal and shear problems decouple). Reads
the case's constant/mechanicalProperties and constant/effects, the 3D fracture table of a
unilateral fracture (with its 'opening' column) and the fault surface .vtp, as pennyError.py
does (whose readers this script uses).

Prints, as "key value" lines:
  * relL2Error: ||g_h - g||_L2(Gamma) / ||g||_L2(Gamma), the nodal openings interpolated (P1
    linear, P2 quadratic) on the fault triangles, 16 x 7 points per triangle;
    relL2ErrorLumped: the same with nodal quadrature; amplitudeRatio: the least-squares factor
    of computed over exact g at the nodes (the cube's finite-size factor once the mesh is
    fine);
  * over the open nodes: maxTau = max |tau| / p, maxSigmaNError = max |sigma_n + p| / p;
  * over the non-tip nodes: minOpening = min g / max g_exact, maxEffectiveStress =
    max sigma'_n / p (sigma'_n = sigma_n + p), maxComplementarity = max |g sigma'_n| / (p max g);
  * the number of nodes in each state.

--maxError E and --maxTraction T turn these into checks: exit 3 when relL2Error > E or when
maxTau or maxSigmaNError > T (or when no node is open). Exit 1 on bad input, 2 on a bad
command line.

Usage: pennyOpeningError.py [-case DIR] [-time T] [-fracture NAME] [-p P]
                            [--maxError E] [--maxTraction T]
"""

import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pennyError import (COLUMNS3D, InputError, flatDisc, latestTime, number,  # noqa: E402
                        numberList, parseDict, readTable, referenceRule, shape)

COLUMNS = COLUMNS3D[:-1] + ["opening", "state"]


def caseParameters(case, fracture, time):
    """E, nu, the remote stress tensor (zero without initialStress) and p at `time` (None when
    the pressure is not a constant: then -p must give it)."""
    path = os.path.join(case, "constant/mechanicalProperties")
    d = parseDict(path)
    if "E" in d and "nu" in d:
        E, nu = number(path, "E", d["E"]), number(path, "nu", d["nu"])
    elif "lambda" in d and "mu" in d:
        lam, mu = number(path, "lambda", d["lambda"]), number(path, "mu", d["mu"])
        E, nu = mu * (3 * lam + 2 * mu) / (lam + mu), lam / (2 * (lam + mu))
    else:
        raise InputError(f"{path}: expected the keys E and nu (or lambda and mu)")
    path = os.path.join(case, "constant/effects")
    d = parseDict(path) if os.path.exists(path) else {}
    s, p = np.zeros(6), None
    for name, e in d.items():
        if name == "FoamFile" or not isinstance(e, dict) or e.get("active", ["yes"])[0] == "no":
            continue
        kind = e.get("type", ["?"])[0]
        if kind == "initialStress":
            if "gradient" in e:
                raise InputError(f"{path}: {name}/gradient: the formula needs a uniform stress")
            s += numberList(path, name + "/stress", e.get("stress", []), 6)
        elif kind == "fracturePressure":
            if e.get("fracture", ["?"])[0] != fracture:
                continue
            v = e.get("pressure", [])
            p = number(path, name + "/pressure", v) if len(v) == 1 else None
        else:
            raise InputError(f"{path}: effect '{name}' ({kind}): the formula has a uniform "
                             "remote stress and a fracture pressure only")
    sigma0 = np.array([[s[0], s[3], s[5]], [s[3], s[1], s[4]], [s[5], s[4], s[2]]])
    return E, nu, sigma0, p


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("-case", default=".")
    ap.add_argument("-time", default=None, help="time folder (default: the latest)")
    ap.add_argument("-fracture", default="fault")
    ap.add_argument("-p", type=float, default=None,
                    help="fracture pressure [Pa] (default: the case's constant pressure)")
    ap.add_argument("--maxError", type=float, help="check: relative L2 error <= this")
    ap.add_argument("--maxTraction", type=float,
                    help="check: maxTau and maxSigmaNError <= this")
    try:
        args = ap.parse_args(argv)
    except SystemExit as e:
        return 0 if e.code == 0 else 2

    case = args.case
    time = args.time or latestTime(case, args.fracture)
    tablePath = os.path.join(case, time, "fractures", args.fracture + ".dat")
    t = readTable(tablePath, COLUMNS)[0]
    E, nu, sigma0, p = caseParameters(case, args.fracture, time)
    p = args.p if args.p is not None else p
    if p is None or not p > 0:
        raise InputError(f"{case}: no constant fracturePressure > 0 on '{args.fracture}' "
                         "(give -p)")
    state, g = t["state"], t["opening"]
    vtpPath = os.path.join(case, "VTK", "fractures", f"{args.fracture}_{time}.vtp")
    xyz, n, tri, order, tips, centre, d, r, a = flatDisc(t, tablePath, vtpPath)

    sigmaNInf = (sigma0 @ n) @ n
    dp = p + sigmaNInf
    if dp <= 0:
        raise InputError(f"{case}: net pressure p + sigma_n_inf = {dp:g} Pa <= 0: the disc "
                         "stays closed")
    amp = 8 * (1 - nu * nu) * dp / (math.pi * E)
    exact = lambda rr: amp * np.sqrt(np.maximum(a * a - rr * rr, 0.0))

    v0, v1, v2 = xyz[tri[:, 0]], xyz[tri[:, 1]], xyz[tri[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(v1 - v0, v2 - v0), axis=1)
    P, W = referenceRule()
    num = shape(P, order) @ g[tri].T
    X = np.einsum("qk,tkd->qtd", P, np.stack([v0, v1, v2], axis=1))
    dq = X - centre
    rq = np.linalg.norm(dq - np.einsum("qt,d->qtd", dq @ n, n), axis=2)
    ex = exact(rq)
    wq = np.outer(W, area)
    err = math.sqrt((wq * (num - ex) ** 2).sum() / (wq * ex ** 2).sum())
    wn = np.zeros(len(xyz))
    for k in range(tri.shape[1]):
        np.add.at(wn, tri[:, k], area * ((1 / 3) if order == 1 else (1 / 12 if k < 3 else 1 / 4)))
    exn = np.where(tips, 0.0, exact(r))
    errLumped = math.sqrt((wn * (g - exn) ** 2).sum() / (wn * exn ** 2).sum())
    ratio = (wn * g * exn).sum() / (wn * exn ** 2).sum()

    isOpen = state == "open"
    inner = state != "tip"
    gMax = amp * a
    mx = lambda x: float(np.max(x)) if len(x) else float("nan")
    maxTau = mx(t["tauMagnitude"][isOpen] / p)
    maxSigmaN = mx(np.abs(t["sigmaN"][isOpen] + p) / p)
    effective = t["sigmaN"][inner] + p
    out = [
        ("table", tablePath), ("surface", vtpPath),
        ("elements", f"P{order} triangles {len(tri)}, nodes {len(xyz)}"),
        ("disc", f"centre ({' '.join(f'{c:.6g}' for c in centre)}) radius {a:.9g} m "
                 f"normal ({' '.join(f'{c:.6g}' for c in n)})"),
        ("E nu", f"{E:.6g} {nu:.6g}"),
        ("pressure", f"p {p:.6g} Pa, sigmaN_inf {sigmaNInf:.6g} Pa, net {dp:.6g} Pa"),
        ("centreOpeningExact", f"{gMax:.6e} m"),
        ("centreOpeningNearest", f"{g[np.argmin(r)]:.6e} m at r = {r.min():.3g} m"),
        ("relL2Error", f"{err:.6e}"),
        ("relL2ErrorLumped", f"{errLumped:.6e}"),
        ("amplitudeRatio", f"{ratio:.6f}"),
        ("openNodes", f"{int(isOpen.sum())} of {int(inner.sum())} non-tip nodes"),
        ("maxTau", f"{maxTau:.6e}"),
        ("maxSigmaNError", f"{maxSigmaN:.6e}"),
        ("minOpening", f"{mx(-g[inner]) * -1 / gMax:.6e}"),
        ("maxEffectiveStress", f"{mx(effective / p):.6e}"),
        ("maxComplementarity", f"{mx(np.abs(g[inner] * effective)) / (p * gMax):.6e}"),
        ("states", " ".join(f"{s} {int((state == s).sum())}"
                            for s in ("stick", "slip", "open", "tip"))),
    ]
    width = max(len(k) for k, _ in out)
    for k, v in out:
        print(f"{k:<{width}}  {v}")
    failed = []
    if args.maxError is not None and not err <= args.maxError:
        failed.append(f"relL2Error {err:.3e} > {args.maxError:g}")
    if args.maxTraction is not None:
        if not isOpen.any():
            failed.append("traction: no open node to check")
        elif not (maxTau <= args.maxTraction and maxSigmaN <= args.maxTraction):
            failed.append(f"traction on open faces {maxTau:.3e}, {maxSigmaN:.3e} > "
                          f"{args.maxTraction:g}")
    for f in failed:
        print("FAILED:", f)
    return 3 if failed else 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except InputError as e:
        print("pennyOpeningError.py: error:", e, file=sys.stderr)
        sys.exit(1)
