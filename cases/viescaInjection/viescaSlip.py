#!/usr/bin/python3
"""The slip profile of the 2D injection benchmark (Viesca 2021), computed from the crack equation.

Usage: viescaSlip.py --T T [--points N]   prints the self-similar slip profile of T
       viescaSlip.py --check              the solver's self-checks (exit 1 if one fails)

Reference: Viesca, R. C. (2021), Self-similar fault slip in response to fluid injection,
J. Fluid Mech. 928, A29. This module solves the problem it poses, independently of the finite
elements of libfriction and of any published code; only the limits quoted below are the paper's.

The problem. A straight fault (the x axis) between two elastic half-planes in plane strain
(shear modulus mu, Poisson ratio nu), under uniform initial effective normal stress sigma'_0
(compression positive here) and shear stress tau_0, with constant friction f. A pressure change
dp held at x = 0 from t = 0 diffuses along the fault: dp(x, t) = dp erfc(|x| / L), L = sqrt(4
alpha t). The slip delta(x, t) is the jump of the displacement across the fault (the two faces'
relative motion, not one face's displacement), taken positive in the direction of tau_0. The
fault slips on |x| < a(t) and there the shear stress equals its strength:

    tau_0 - (mu' / (2 pi)) PV int_{-a}^{a} (d delta/ds) / (x - s) ds = f (sigma'_0 - dp(x, t)),

mu' = mu / (1 - nu) (in-plane slip; E / (2 (1 - nu^2)) in terms of E). The elastic term is the
stress change of a distribution of edge dislocations of density -d delta/ds on an infinite
plane (Rice 1980; Segall 2010, ch. 4); its sign makes slip relieve the stress that drives it:
a uniform stress drop dtau over |x| < a gives delta = (2 dtau / mu') sqrt(a^2 - x^2), the
classical mode II crack (docs/method.md: |slip| = 4 (1 - nu^2) dtau / E sqrt(a^2 - x^2)). With
delta(+-a) = 0 and a bounded stress at x = +-a (no stress intensity: friction has no strength
to spare at the tips), the problem is self-similar: a = lambda L and, in X = x / a,

    delta(x, t) = (f dp a / mu') D(X),   (1 / (2 pi)) PV int_{-1}^{1} D'(S) / (X - S) dS = g(X),
    g(X) = erfc(lambda |X|) - T,   T = (f sigma'_0 - tau_0) / (f dp),

one parameter T, the stress drop g in units of f dp.

The method. D(X) = sum_n b_n sqrt(1 - X^2) U_{n-1}(X) = sum_n b_n sin(n theta), X = cos theta
(U the Chebyshev polynomials of the second kind). Each mode has a closed-form stress drop,
(1 / (2 pi)) PV int (d/dS)[sin(n phi)] / (X - S) dS = (n / 2) U_{n-1}(X), and the U_{n-1} are
orthogonal with weight sqrt(1 - X^2), so b_n = (4 / (n pi)) int_0^pi g(cos theta) sin(n theta)
sin(theta) d theta exactly: no linear system. g is even (odd n only) and, through
erfc(lambda |X|) = 1 - (2 / sqrt(pi)) (lambda |X| - (lambda |X|)^3 / 3 + ...), has kinks at
X = 0 that alone would make b_n fall as n^-3. The first two are removed in closed form: the
stress drops |X| and |X|^3 have the slips
    D_1(X) = (2 / pi) (sqrt(1 - X^2) + X^2 arccosh(1 / |X|)),
    D_3(X) = (1 / pi) ((2/3 + X^2) sqrt(1 - X^2) + X^4 arccosh(1 / |X|))
(the second found by fitting these three functions to a 3 000-mode series, to 1e-15; --check
compares both with the plain series), so the series expands only g + c_1 |X| + c_3 |X|^3
(c_1 = 2 lambda / sqrt(pi), c_3 = -2 lambda^3 / (3 sqrt(pi))), whose b_n fall as n^-7, and
D = sum_n b_n sin(n theta) - c_1 D_1 - c_3 D_3. The integrals are Gauss-Legendre on [0, pi/2],
where that part of g is smooth.

lambda is the root of the bounded-stress condition: near X = 1 the slip is
D ~ K sqrt(1 - X^2) with K = sum_n n b_n - c_1 4 / pi - c_3 8 / (3 pi) (the limits of
D_1 / sqrt(1 - X^2) and D_3 / sqrt(1 - X^2) at X = 1; K is a stress intensity), and lambda
makes K = 0, so that D vanishes as (1 - X)^{3/2}. Solved by bisection on K(lambda). It agrees with the paper's closed condition
T = (2/pi) int_0^{pi/2} erfc(lambda sin theta) d theta (viescaError.lambdaOf) to 1e-10.

Checks (--check): the truncation (N against 2N modes); the same slip from the crack's Green's
function, D(theta) = (2/pi) int_0^pi g(cos phi) sin(phi) ln|sin((theta+phi)/2) /
sin((theta-phi)/2)| d phi, by graded quadrature (an independent route to the same equation);
lambda against viescaError.lambdaOf; and the paper's limits:
* marginally pressurised (T -> 1, lambda ~ (pi^{3/2}/4)(1 - T)): g ~ (1 - T) - c |X|, so
  D ~ (1 - T) (sqrt(1 - X^2) - X^2 arccosh(1 / |X|)), i.e. delta ~ (4 lambda^2 / pi^{3/2})
  (f dp L / mu') (sqrt(1 - X^2) - X^2 arctanh(sqrt(1 - X^2)));
* critically stressed (T -> 0, lambda ~ 2 / (pi^{3/2} T)): outer slip (a point load at x = 0)
  delta ~ (4 / pi^{3/2}) (f dp L / mu') (arctanh(sqrt(1 - X^2)) - sqrt(1 - X^2)), and the slip
  at x = 0, delta(0) ~ (4 / pi^{3/2}) (f dp L / mu') (ln(2 lambda) + gamma / 2 - 1/(4 lambda^2))
  (gamma Euler's constant; the paper's inner solution at x = 0).

The factor 2. PyFracX (GeoEnergyLab-EPFL/PyFracX-Examples, ReferenceSolutions/FDFR/
Plane_TwoD_frictional_ruptures.py) writes these limits with the coefficients 2 lambda^2 /
pi^{3/2}, 2 / pi^{3/2} and the same scale sqrt(4 alpha t) f dp / muprime, where its muprime is
documented as "the plane-strain Young's modulus (mode II)", E' = E / (1 - nu^2) = 2 mu / (1 - nu):
twice the mu' above. With muprime = E' its slip is ours (the jump) to the asymptotes' order;
evaluated with muprime = mu / (1 - nu) it is half the jump, which is the 1.97-1.99 ratio found
against our finite elements. So the paper's slip is the jump, and mu' = mu/(1 - nu) goes with
the coefficients 4 lambda^2 / pi^{3/2} and 4 / pi^{3/2}; --check verifies the ratio is 2.
"""
import argparse
import math
import os
import sys

import numpy

_erfc = numpy.vectorize(math.erfc, otypes=[float])


def _kinkSlips(X):
    """D_1 and D_3 of the module docstring (the slips of the stress drops |X| and |X|^3) at X."""
    x = numpy.abs(numpy.asarray(X, dtype=float))
    r = numpy.sqrt(numpy.clip(1 - x * x, 0, None))
    # x^k arccosh(1/x) -> 0 as x -> 0 (k >= 2): guard the division at x = 0.
    acosh = numpy.where(x > 0, numpy.arccosh(1 / numpy.where(x > 0, numpy.minimum(x, 1), 1)), 0.0)
    d1 = (2 / math.pi) * (r + x**2 * acosh)
    d3 = (1 / math.pi) * ((2 / 3 + x**2) * r + x**4 * acosh)
    return d1, d3


def _kinkCoefficients(lam):
    """c_1, c_3 of the module docstring: erfc(lam|X|) = 1 - c_1 |X| - c_3 |X|^3 + O(|X|^5)."""
    return 2 * lam / math.sqrt(math.pi), -2 * lam**3 / (3 * math.sqrt(math.pi))


class SlipShape:
    """D(X) of the module docstring for one T: the slip in units of f dp a / mu'.

    modes: odd n up to this (the series' length); points: Gauss-Legendre nodes on [0, pi/2].
    """

    def __init__(self, T, modes=401, points=800):
        if not 0 < T < 1:
            raise ValueError(f"T = {T}: the benchmark slips only for 0 < T < 1")
        self.T = T
        self.n = numpy.arange(1, modes + 1, 2)
        x, w = numpy.polynomial.legendre.leggauss(points)
        self._theta = (x + 1) * math.pi / 4
        self._w = w * math.pi / 4
        self._basis = numpy.sin(numpy.outer(self._theta, self.n))  # sin(n theta) at the nodes
        self._erfcArg = numpy.cos(self._theta)
        self.lam = self._solveLambda()
        self.b = self._coefficients(self.lam)
        self.c1, self.c3 = _kinkCoefficients(self.lam)

    def _coefficients(self, lam):
        """b_n of the smooth part g + c_1 X + c_3 X^3 (odd n), Gauss-Legendre on [0, pi/2]."""
        X = self._erfcArg
        c1, c3 = _kinkCoefficients(lam)
        smooth = _erfc(lam * X) + c1 * X + c3 * X**3 - self.T
        weights = smooth * numpy.sin(self._theta) * self._w
        return (8 / (self.n * math.pi)) * (weights @ self._basis)

    def stressIntensity(self, lam):
        """K(lambda) = lim D / sqrt(1 - X^2) at X = 1 (0 for the benchmark's lambda)."""
        c1, c3 = _kinkCoefficients(lam)
        return float(self.n @ self._coefficients(lam)) - c1 * 4 / math.pi - c3 * 8 / (3 * math.pi)

    def _solveLambda(self):
        # K(0) = 2 (1 - T) > 0 and K falls with lambda to -2 T: bracket, then bisect.
        lo, hi = 0.0, 1.0
        while self.stressIntensity(hi) > 0:
            lo, hi = hi, 2 * hi
            if hi > 1e4:
                raise ValueError(f"T = {self.T}: no lambda below 1e4")
        for _ in range(200):
            mid = (lo + hi) / 2
            if mid in (lo, hi):
                break
            if self.stressIntensity(mid) > 0:
                lo = mid
            else:
                hi = mid
        return (lo + hi) / 2

    def __call__(self, X):
        """D at X (any shape); 0 outside |X| < 1."""
        X = numpy.asarray(X, dtype=float)
        out = numpy.zeros_like(X)
        inside = numpy.abs(X) < 1
        theta = numpy.arccos(X[inside])
        d1, d3 = _kinkSlips(X[inside])
        out[inside] = numpy.sin(numpy.outer(theta, self.n)) @ self.b - self.c1 * d1 - self.c3 * d3
        return out


def slip(x, t, shape, alpha, f, dp, muPrime):
    """delta(x, t) [m]: the jump, positive in the direction of tau_0 (module docstring)."""
    L = math.sqrt(4 * alpha * t)
    a = shape.lam * L
    return f * dp * a / muPrime * shape(numpy.asarray(x, dtype=float) / a)


def greenSlip(T, lam, X, points=160):
    """D(X) by the crack's Green's function (module docstring), graded Gauss-Legendre."""
    theta = math.acos(X)
    v, w = numpy.polynomial.legendre.leggauss(points)
    v, w = (v + 1) / 2, w / 2
    total = 0.0
    cuts = sorted({0.0, theta, math.pi / 2, math.pi})
    for lo, hi in zip(cuts[:-1], cuts[1:]):
        # Cubic grading towards the end at theta (the logarithm's singularity), or both ends.
        if abs(lo - theta) < 1e-15:
            phi, jac = lo + (hi - lo) * v**3, (hi - lo) * 3 * v**2
        elif abs(hi - theta) < 1e-15:
            phi, jac = hi - (hi - lo) * v**3, (hi - lo) * 3 * v**2
        else:
            phi, jac = lo + (hi - lo) * v, numpy.full_like(v, hi - lo)
        g = _erfc(lam * numpy.abs(numpy.cos(phi))) - T
        kernel = numpy.log(numpy.abs(numpy.sin((theta + phi) / 2) / numpy.sin((theta - phi) / 2)))
        total += float(numpy.sum(w * jac * g * numpy.sin(phi) * kernel))
    return 2 / math.pi * total


def muPrimeOf(E, nu, planeStress=False):
    """mu' = mu / (1 - nu) in plane strain (E / (2 (1 - nu^2))); E / 2 in plane stress."""
    return E / 2 if planeStress else E / (2 * (1 - nu * nu))


def selfCheck():
    """The checks of the module docstring; returns the list of failures (printed as it goes)."""
    sys.dont_write_bytecode = True  # no __pycache__ in the case folder
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from viescaError import lambdaOf

    fails = []

    def check(ok, text):
        print(("ok    " if ok else "FAIL  ") + text)
        if not ok:
            fails.append(text)

    X = numpy.array([0.0, 0.05, 0.2, 0.4, 0.6, 0.8, 0.95, 0.99])
    # D_1, D_3 against the plain series of |X| and |X|^3 (2 001 modes; b_n ~ n^-3 there).
    n = numpy.arange(1, 2002, 2)
    v, w = numpy.polynomial.legendre.leggauss(2600)
    th, w = (v + 1) * math.pi / 4, w * math.pi / 4
    basis = numpy.sin(numpy.outer(th, n))
    at = numpy.sin(numpy.outer(numpy.arccos(X), n))
    for k, dk in zip((1, 3), _kinkSlips(X)):
        series = at @ ((8 / (n * math.pi)) * ((numpy.cos(th)**k * numpy.sin(th) * w) @ basis))
        err = numpy.max(numpy.abs(series - dk))
        check(err < 1e-6, f"the slip of the stress drop |X|^{k} in closed form against its "
              f"series: {err:.1e}")
    for T in (0.1, 0.5, 0.9):
        s, s2 = SlipShape(T), SlipShape(T, modes=801, points=1600)
        lamRef = lambdaOf(T)
        check(abs(s.lam - lamRef) <= 1e-10 * lamRef,
              f"T = {T}: lambda {s.lam:.12g} (tip condition of the series) against "
              f"{lamRef:.12g} (the paper's integral, viescaError.lambdaOf)")
        d, d2 = s(X), s2(X)
        trunc = numpy.max(numpy.abs(d - d2)) / numpy.max(numpy.abs(d2))
        check(trunc < 1e-9, f"T = {T}: 401 against 801 modes: {trunc:.2e} of max D")
        green = numpy.array([greenSlip(T, s.lam, x) for x in X])
        gerr = numpy.max(numpy.abs(d - green)) / numpy.max(numpy.abs(d))
        check(gerr < 1e-7, f"T = {T}: the Green's-function integral gives the same D to {gerr:.2e}")
        near = s(numpy.array([1 - 1e-4]))[0] / (1e-4) ** 1.5
        far = s(numpy.array([1 - 1e-3]))[0] / (1e-3) ** 1.5
        check(abs(near / far - 1) < 0.05 and near > 0,
              f"T = {T}: D ~ (1 - X)^(3/2) at the tip (D/(1-X)^1.5 = {near:.4g}, {far:.4g})")
    # Marginally pressurised: the full solution against its leading order, error O(lambda^2).
    for T in (0.99, 0.999):
        s = SlipShape(T)
        Xm = X[1:]
        asym = (1 - T) * (numpy.sqrt(1 - Xm**2) - Xm**2 * numpy.arccosh(1 / Xm))
        err = numpy.max(numpy.abs(s(Xm) - asym)) / numpy.max(asym)
        check(err < 2 * s.lam**2, f"T = {T} (lambda {s.lam:.4g}): marginal limit to {err:.2e} "
              f"(< 2 lambda^2 = {2 * s.lam**2:.2e})")
        # PyFracX's form, 2 lambda^2 / pi^{3/2} (...) times sqrt(4 alpha t) f dp / muprime,
        # with muprime = mu' = mu/(1 - nu): the ratio of our slip to it, lambda D / that.
        pyfracx = 2 * s.lam**2 / math.pi**1.5 * (numpy.sqrt(1 - Xm**2) - Xm**2 * numpy.arctanh(
            numpy.sqrt(1 - Xm**2)))
        ratio = s.lam * s(Xm) / pyfracx
        check(numpy.all(numpy.abs(ratio - 2) < 4 * s.lam**2),
              f"T = {T}: our slip / PyFracX's marginal formula with muprime = mu/(1-nu): "
              f"{ratio.min():.5f}-{ratio.max():.5f} (2: its muprime is E/(1-nu^2))")
    # Critically stressed: outer profile O(1/lambda^2) away from the centre, and the centre.
    for T in (0.02, 0.01):
        s = SlipShape(T, modes=801, points=1600)
        Xo = numpy.array([0.3, 0.5, 0.7, 0.9])
        outer = 4 / math.pi**1.5 * (numpy.arctanh(numpy.sqrt(1 - Xo**2)) - numpy.sqrt(1 - Xo**2))
        err = numpy.max(numpy.abs(s.lam * s(Xo) - outer)) / numpy.max(outer)
        check(err < 5 / s.lam**2, f"T = {T} (lambda {s.lam:.4g}): outer limit to {err:.2e} "
              f"(< 5/lambda^2 = {5 / s.lam**2:.2e})")
        centre = 4 / math.pi**1.5 * (math.log(2 * s.lam) + 0.5772156649015329 / 2
                                     - 1 / (4 * s.lam**2))
        err = abs(s.lam * s(numpy.array([0.0]))[0] - centre) / centre
        check(err < 1 / s.lam**3, f"T = {T}: slip at x = 0 against the inner limit to {err:.2e}")
    return fails


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--T", type=float)
    ap.add_argument("--points", type=int, default=21)
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args()
    if a.check:
        fails = selfCheck()
        print(f"{'FAIL' if fails else 'PASS'}: {len(fails)} check(s) failed")
        return 1 if fails else 0
    if a.T is None:
        ap.error("give --T or --check")
    s = SlipShape(a.T)
    print(f"T {a.T:g}  lambda {s.lam:.10g}")
    print("# xi = x/sqrt(4 alpha t)  X = x/a  slip/(f dp sqrt(4 alpha t)/mu')  slip/(f dp a/mu')")
    for X in numpy.linspace(0, 1, a.points):
        D = s(numpy.array([X]))[0]
        print(f"{X * s.lam:.6f}  {X:.6f}  {s.lam * D:.10e}  {D:.10e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
