#!/usr/bin/python3
"""The slipping half-length a(t) of the 2D injection benchmark against Viesca (2021).

Usage: viescaError.py CASE_DIR --T T --alpha ALPHA [--fracture fault] [--check]

Viesca, R. C. (2021), Self-similar fault slip in response to fluid injection, J. Fluid Mech.
928, A29: a fault of constant friction f under uniform initial stresses (sigma'_0 effective
normal, tau_0 shear), a pressure change dp held at x = 0 from t = 0 and diffusing along the
fault (dp erfc(|x| / sqrt(4 alpha t))), slips over |x| < a(t) = lambda(T) sqrt(4 alpha t),
T = (f sigma'_0 - tau_0) / (f dp). lambda(T) is the root of the condition that the stress
intensity vanishes at the rupture's ends (the paper's equation for lambda, written with
x = a sin(theta)):

    T = (2/pi) * integral_0^{pi/2} erfc(lambda sin(theta)) dtheta,

solved here to 1e-12; its limits are the paper's: lambda ~ 2/(pi^{3/2} T) for T << 1
(critically stressed) and lambda ~ (pi^{3/2}/4)(1 - T) for T -> 1 (marginally pressurised).
For T >= 1 nothing slips (a = 0).

The numerical a(t) of a written time is the half-length of the nodes in state 'slip',
measured halfway to the first node that is not: a = (a_slip + a_next) / 2 on each side, the
two sides averaged; its resolution is h/2 (h the fault's node spacing). Prints one row per
written time and the largest relative error. --check makes it a test (exit 1 otherwise):
every row must have |a_h - a| <= h/2 + 0.005 a, the mesh's resolution plus 0.5 % for the
finite body (its far boundary is held at 4 fault half-lengths).
"""
import argparse
import math
import os
import sys

import numpy


def lambdaOf(T):
    """lambda(T) of the equation above (0 for T >= 1), by bisection on the monotone T(lambda)."""
    if T >= 1:
        return 0.0
    # Gauss-Legendre on [0, pi/2], 400 points: the integrand is analytic, and resolved down to
    # its scale 1/lambda near theta = 0 for lambda up to ~1e3 (checked against adaptive
    # quadrature: 1e-12).
    nodes, weights = numpy.polynomial.legendre.leggauss(400)
    theta = (nodes + 1) * math.pi / 4

    def Tof(lam):
        return 2 / math.pi * (math.pi / 4) * sum(
            w * math.erfc(lam * math.sin(th)) for th, w in zip(theta, weights))

    lo, hi = 0.0, 1.0
    while Tof(hi) > T:
        hi *= 2
    for _ in range(200):
        mid = (lo + hi) / 2
        if Tof(mid) > T:
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2


def readTable(path):
    lines = open(path).read().splitlines()
    header = lines[0][1:].split()
    rows = [l.split() for l in lines if l and not l.startswith("#")]
    if not rows:
        raise SystemExit(f"{path}: no rows")
    ix, ist = header.index("x"), header.index("state")
    return [(float(r[ix]), r[ist]) for r in rows]


def halfLength(rows):
    """Half-length of the slipping zone around x = 0, each side halfway to the next node."""
    rows = sorted(rows)
    xs = [x for x, _ in rows]
    slipping = [i for i, (_, s) in enumerate(rows) if s == "slip"]
    if not slipping:
        return 0.0
    lo, hi = min(slipping), max(slipping)
    right = (xs[hi] + xs[min(hi + 1, len(xs) - 1)]) / 2
    left = (xs[lo] + xs[max(lo - 1, 0)]) / 2
    return (right - left) / 2


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case")
    ap.add_argument("--T", type=float, required=True)
    ap.add_argument("--alpha", type=float, required=True)
    ap.add_argument("--fracture", default="fault")
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args()
    lam = lambdaOf(a.T)
    times = sorted((float(d), d) for d in os.listdir(a.case)
                   if d.replace(".", "", 1).replace("e-", "", 1).isdigit() and float(d) > 0
                   and os.path.isfile(os.path.join(a.case, d, "fractures", a.fracture + ".dat")))
    if not times:
        raise SystemExit(f"{a.case}: no time folder with fractures/{a.fracture}.dat")
    print(f"T {a.T:g}  lambda {lam:.10g}")
    print("time  diffusionLength  aNumerical  aReference  relError")
    worst, failures = 0.0, []
    for t, name in times:
        L = math.sqrt(4 * a.alpha * t)
        rows = readTable(os.path.join(a.case, name, "fractures", a.fracture + ".dat"))
        xs = sorted(x for x, _ in rows)
        h = sorted(b - c for b, c in zip(xs[1:], xs[:-1]))[len(xs) // 2]  # the median spacing
        aNum = halfLength(rows)
        aRef = lam * L
        err = abs(aNum - aRef) / aRef if aRef > 0 else aNum
        worst = max(worst, err)
        print(f"{name}  {L:.6g}  {aNum:.6g}  {aRef:.6g}  {err:.3e}")
        if abs(aNum - aRef) > h / 2 + 0.005 * aRef:
            failures.append(f"time {name}: |a_h - a| = {abs(aNum - aRef):.4g} m > h/2 + 0.5 % "
                            f"= {h / 2 + 0.005 * aRef:.4g} m (h = {h:.4g} m)")
    print(f"maxRelError {worst:.3e}")
    if a.check and failures:
        print("FAIL: " + "; ".join(failures))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
