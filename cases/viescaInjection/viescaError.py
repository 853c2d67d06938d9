#!/usr/bin/python3
"""The slipping half-length a(t) and the slip of the 2D injection benchmark against Viesca (2021).

Usage: viescaError.py CASE_DIR --T T --alpha ALPHA [--dp DP] [--fracture fault] [--check]

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

The slip: the table's `slip` column against the reference delta(x, t) of viescaSlip.py (the
crack equation solved by a Chebyshev series; the jump of the displacement, mu' = mu/(1 - nu) in
plane strain, f from constant/fractureProperties, E and nu from
constant/mechanicalProperties, dp the well's held `pressure` in constant/effects or --dp).
The table's slip has the sign opposite to tau (docs/method.md, section 2), so the reference
is given the sign of -tau at the slipping nodes: a slip of the wrong sign is an error of
200 %. Two norms over the whole fault (the reference is 0 off |x| < a): the largest
|delta_h - delta| relative to max delta, and the L2 norm (trapezoid rule on the nodes)
relative to that of delta. --check requires both <= h/(2a) + 0.015: the slipping zone ends
within h/2 of the true tip (above), and the slip of a crack scales with its length, so a zone
misplaced by h/2 costs h/(2a) of the slip; 1.5 % for the mesh that grows from h at the fault
to 6 m far away and for the finite body (measured: 1.1 % at h = 0.05 m for T = 0.1 at
a = 7.3 m, 0.3 % with a far size of 1.5 m; docs/study-viesca.md). A slip 2x off (50 % or
100 %) or of the wrong sign fails at every written time of the case.
"""
import argparse
import math
import os
import re
import sys

import numpy

sys.dont_write_bytecode = True  # no __pycache__ in the case folder
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from viescaSlip import SlipShape, muPrimeOf, slip  # noqa: E402 (the module next to this one)


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
    """Rows (x, state, slip, tau) of a fracture table, by its header's column names."""
    lines = open(path).read().splitlines()
    header = lines[0][1:].split() if lines and lines[0].startswith("#") else []
    missing = [c for c in ("x", "state", "slip", "tau") if c not in header]
    if missing:
        raise SystemExit(f"{path}:1: the header lacks the column(s) {' '.join(missing)}")
    rows = [l.split() for l in lines if l and not l.startswith("#")]
    if not rows:
        raise SystemExit(f"{path}: no rows")
    ix, ist, isl, ita = (header.index(c) for c in ("x", "state", "slip", "tau"))
    return [(float(r[ix]), r[ist], float(r[isl]), float(r[ita])) for r in rows]


def readKey(path, key, pattern=r"[-+0-9.eE]+"):
    """The value of `key value;` in an OpenFOAM-style dictionary (first match); exits if absent."""
    try:
        text = open(path).read()
    except OSError as e:
        raise SystemExit(f"{path}: {e.strerror}")
    text = re.sub(r"//.*", "", text)
    m = re.search(r"(?:^|[\s{;])" + key + r"\s+(" + pattern + r")\s*;", text)
    if not m:
        raise SystemExit(f"{path}: no '{key} <value>;' found")
    return m.group(1)


def slipErrors(rows, t, shape, alpha, f, dp, muPrime):
    """(max |delta_h - delta| / max delta, L2 error / L2 norm of delta) over the fault's nodes."""
    rows = sorted(rows)
    x = numpy.array([r[0] for r in rows])
    tauSlip = [r[3] for r in rows if r[1] == "slip"]
    sign = -1.0 if numpy.median(tauSlip) > 0 else 1.0  # the slip opposes tau (method.md §2)
    ref = sign * slip(x, t, shape, alpha, f, dp, muPrime)
    err = numpy.array([r[2] for r in rows]) - ref
    dx = numpy.diff(x)

    def integral(v):
        return float(numpy.sum((v[1:] ** 2 + v[:-1] ** 2) / 2 * dx))

    return (float(numpy.max(numpy.abs(err)) / numpy.max(numpy.abs(ref))),
            math.sqrt(integral(err) / integral(ref)))


def halfLength(rows):
    """Half-length of the slipping zone around x = 0, each side halfway to the next node."""
    rows = sorted(rows)
    xs = [r[0] for r in rows]
    slipping = [i for i, r in enumerate(rows) if r[1] == "slip"]
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
    ap.add_argument("--dp", type=float, help="the held pressure change [Pa] (default: the "
                    "well's 'pressure' in constant/effects)")
    ap.add_argument("--fracture", default="fault")
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args()
    lam = lambdaOf(a.T)
    if not 0 < a.T < 1:
        raise SystemExit(f"--T {a.T:g}: the benchmark slips only for 0 < T < 1")
    mech = os.path.join(a.case, "constant", "mechanicalProperties")
    E, nu = float(readKey(mech, "E")), float(readKey(mech, "nu"))
    planeStress = readKey(mech, "planeStress", r"\w+") in ("yes", "on", "true") \
        if re.search(r"(?m)^\s*planeStress\s", open(mech).read()) else False
    muPrime = muPrimeOf(E, nu, planeStress)
    fric = float(readKey(os.path.join(a.case, "constant", "fractureProperties"),
                         "frictionCoefficient"))
    dp = a.dp if a.dp is not None else float(readKey(
        os.path.join(a.case, "constant", "effects"), "pressure"))
    shape = SlipShape(a.T)
    times = sorted((float(d), d) for d in os.listdir(a.case)
                   if d.replace(".", "", 1).replace("e-", "", 1).isdigit() and float(d) > 0
                   and os.path.isfile(os.path.join(a.case, d, "fractures", a.fracture + ".dat")))
    if not times:
        raise SystemExit(f"{a.case}: no time folder with fractures/{a.fracture}.dat")
    print(f"T {a.T:g}  lambda {lam:.10g}  (slip: f {fric:g}, dp {dp:g} Pa, mu' {muPrime:.6g} Pa)")
    print("time  diffusionLength  aNumerical  aReference  relError  slipMaxError  slipL2Error  "
          "slipBound")
    worst, worstSlip, worstL2, failures = 0.0, 0.0, 0.0, []
    for t, name in times:
        L = math.sqrt(4 * a.alpha * t)
        rows = readTable(os.path.join(a.case, name, "fractures", a.fracture + ".dat"))
        xs = sorted(r[0] for r in rows)
        h = sorted(b - c for b, c in zip(xs[1:], xs[:-1]))[len(xs) // 2]  # the median spacing
        aNum = halfLength(rows)
        aRef = lam * L
        err = abs(aNum - aRef) / aRef if aRef > 0 else aNum
        worst = max(worst, err)
        slipMax, slipL2 = slipErrors(rows, t, shape, a.alpha, fric, dp, muPrime)
        worstSlip, worstL2 = max(worstSlip, slipMax), max(worstL2, slipL2)
        bound = h / (2 * aRef) + 0.015
        print(f"{name}  {L:.6g}  {aNum:.6g}  {aRef:.6g}  {err:.3e}  {slipMax:.3e}  {slipL2:.3e}  "
              f"{bound:.3e}")
        if abs(aNum - aRef) > h / 2 + 0.005 * aRef:
            failures.append(f"time {name}: |a_h - a| = {abs(aNum - aRef):.4g} m > h/2 + 0.5 % "
                            f"= {h / 2 + 0.005 * aRef:.4g} m (h = {h:.4g} m)")
        if not max(slipMax, slipL2) <= bound:
            failures.append(f"time {name}: slip error {max(slipMax, slipL2):.4g} "
                            f"(max {slipMax:.4g}, L2 {slipL2:.4g}) > h/(2a) + 1.5 % = {bound:.4g}")
    print(f"maxRelError {worst:.3e}")
    print(f"maxSlipError {worstSlip:.3e}")
    print(f"maxSlipL2Error {worstL2:.3e}")
    if a.check and failures:
        print("FAIL: " + "; ".join(failures))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
