#!/usr/bin/python3
"""The slip-weakening injection benchmark of Garagash & Germanovich (2012) against the solver.

Usage: gg12Check.py CASE_DIR [--fracture fault] [--check]

Garagash, D. I. and Germanovich, L. N. (2012), Nucleation and arrest of dynamic slip on a
pressurized fault, J. Geophys. Res. 117, B10310: a 2D fault under uniform initial stresses
(sigma'_0 effective normal, tau_0 shear) with linear slip-weakening friction from f_p to f_r
over d_c, and a pressure change dp held at x = 0 from t = 0, diffusing along the fault
(dp erfc(|x| / sqrt(4 alpha t))). Scales: delta_w = f_p d_c / (f_p - f_r) and
a_w = mu' d_c / ((f_p - f_r) sigma'_0), mu' = mu / (1 - nu) in plane strain. For
tau_0 / (f_p sigma'_0) = 0.55, dp / sigma'_0 = 0.5 and f_r / f_p = 0.6 the slipping
half-length a grows quasi-statically along a lower branch until sqrt(4 alpha t) / a_w = 4.914,
a = 1.066 a_w, where the branch folds: the quasi-static equilibrium is lost and a dynamic
rupture nucleates. REFERENCE below is that lower branch, (sqrt(4 alpha t)/a_w, a/a_w), as
digitised from the paper's figure in GeoEnergyLab-EPFL/PyFracX-Examples,
ReferenceSolutions/FDFR/LW-2D-GG12-MP-reference-1.json (commit deb0d7fb5fe1).

The numerical a(t) is viescaError.py's: the half-length of the nodes in state 'slip', each
side halfway to the next node (resolution h/2). --check makes it a test (exit 1 otherwise):
  * every converged time on the lower branch (X <= 4.914): |a_h - a| <= h/2 + 0.02 a_w
    + 0.01 X |da/dX|: the mesh's resolution, and the digitised curve read to about 2 % of a_w
    in a and 1 % in X (the last term where the branch is steep);
  * the loss of equilibrium: the solver's first step with status 'nucleation' comes after
    X = 4.914 (1 - 0.015) and the last converged one before 4.914 (1 + 0.015), 1.5 % for the
    digitised fold;
  * the fold's place from the solver's own signal: the patch's tangent stiffness k (solverStatus
    'patchStiffness') falls to 0 like sqrt(t_fold - t) at a fold, so k^2 of the last converged
    step and of the latest earlier one with a larger k (k changes where a node joins the patch
    or passes d_c), extrapolated linearly to 0, gives t_fold; its X within 1.5 % of 4.914;
  * the half-length at the last converged step within the first bound of 1.066 a_w's branch.
At least 10 times on the branch must be compared (a check over nothing fails).
"""
import argparse
import math
import os
import re
import sys



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


def readTable(path):
    """Rows (x, state) of a fracture table, by its header's column names."""
    lines = open(path).read().splitlines()
    header = lines[0][1:].split() if lines and lines[0].startswith("#") else []
    if "x" not in header or "state" not in header:
        raise SystemExit(f"{path}:1: the header lacks the column x or state")
    rows = [l.split() for l in lines if l and not l.startswith("#")]
    if not rows:
        raise SystemExit(f"{path}: no rows")
    ix, ist = header.index("x"), header.index("state")
    return [(float(r[ix]), r[ist]) for r in rows]


def halfLength(rows):
    """Half-length of the slipping zone around x = 0, each side halfway to the next node (as
    cases/viescaInjection/viescaError.py measures it)."""
    rows = sorted(rows)
    xs = [r[0] for r in rows]
    slipping = [i for i, r in enumerate(rows) if r[1] == "slip"]
    if not slipping:
        return 0.0
    lo, hi = min(slipping), max(slipping)
    right = (xs[hi] + xs[min(hi + 1, len(xs) - 1)]) / 2
    left = (xs[lo] + xs[max(lo - 1, 0)]) / 2
    return (right - left) / 2


# (sqrt(4 alpha t)/a_w, a/a_w) of the lower branch, up to the fold (the last row).
REFERENCE = [(0.323, 0.043), (0.52, 0.072), (0.74, 0.108), (0.98, 0.144), (1.296, 0.186),
             (1.75, 0.257), (2.141, 0.328), (2.573, 0.407), (2.927, 0.467), (3.179, 0.515),
             (3.514, 0.581), (4.042, 0.69), (4.37, 0.79), (4.67, 0.896), (4.809, 0.966),
             (4.914, 1.066)]
FOLD_X, FOLD_A = REFERENCE[-1]
# The dimensionless set the reference is for.
STRESS_RATIO, PRESSURE_RATIO, FRICTION_RATIO = 0.55, 0.5, 0.6


def branch(X):
    """a/a_w and da/dX on the lower branch at X (linear between the digitised points)."""
    for (x0, a0), (x1, a1) in zip(REFERENCE, REFERENCE[1:]):
        if x0 <= X <= x1:
            slope = (a1 - a0) / (x1 - x0)
            return a0 + slope * (X - x0), slope
    raise ValueError(X)


def status(folder):
    text = open(os.path.join(folder, "solverStatus")).read()
    st = re.search(r"\bstatus\s+(\w+)\s*;", text).group(1)
    m = re.search(r"\bpatchStiffness\s+([-+0-9.eE]+)\s*;", text)
    return st, (float(m.group(1)) if m else None)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case")
    ap.add_argument("--fracture", default="fault")
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args()
    c = args.case
    mech, frac, eff = (os.path.join(c, "constant", f) for f in
                       ("mechanicalProperties", "fractureProperties", "effects"))
    E, nu = float(readKey(mech, "E")), float(readKey(mech, "nu"))
    if readKey(mech, "planeStress", r"\w+") not in ("no", "false", "off"):
        raise SystemExit(f"{mech}: the benchmark is in plane strain (planeStress no)")
    fp, fr = float(readKey(frac, "staticCoefficient")), float(readKey(frac, "dynamicCoefficient"))
    dc = float(readKey(frac, "criticalSlip"))
    stress = [float(v) for v in readKey(eff, "stress", r"\([^)]*\)").strip("()").split()]
    sigma0, tau0 = -stress[1], abs(stress[2])
    dp, alpha = float(readKey(eff, "pressure")), float(readKey(eff, "diffusivity"))
    ratios = (tau0 / (fp * sigma0), dp / sigma0, fr / fp)
    if any(abs(a - b) > 1e-9 for a, b in zip(ratios, (STRESS_RATIO, PRESSURE_RATIO, FRICTION_RATIO))):
        raise SystemExit(f"{c}: tau0/(f_p sigma'0), dp/sigma'0, f_r/f_p = {ratios}: the reference "
                         f"is for {STRESS_RATIO}, {PRESSURE_RATIO}, {FRICTION_RATIO}")
    muPrime = E / (2 * (1 + nu)) / (1 - nu)  # mu' = mu/(1 - nu), plane strain
    aw = muPrime * dc / ((fp - fr) * sigma0)
    times = sorted((float(d), d) for d in os.listdir(c)
                   if re.fullmatch(r"[0-9.eE+-]+", d) and os.path.isdir(os.path.join(c, d))
                   and os.path.exists(os.path.join(c, d, "solverStatus")))
    failures, compared, stable, nucleation, h = [], 0, [], None, None
    print(f"# a_w {aw:.6g} m, delta_w {fp * dc / (fp - fr):.6g} m; X = sqrt(4 alpha t)/a_w")
    print("# time X a_h/a_w a_ref/a_w bound status patchStiffness")
    for t, name in times:
        rows = readTable(os.path.join(c, name, "fractures", args.fracture + ".dat"))
        xs = sorted(r[0] for r in rows)
        h = min(b - a for a, b in zip(xs, xs[1:]))
        st, k = status(os.path.join(c, name))
        X = math.sqrt(4 * alpha * t) / aw
        a = halfLength(rows) / aw
        line = f"{name} {X:.5g} {a:.5g}"
        if st == "nucleation":
            nucleation = nucleation or (t, X)
        elif st == "converged":
            stable.append((t, X, a, k))
            if X <= FOLD_X:
                ref, slope = branch(X)
                bound = h / 2 / aw + 0.02 + 0.01 * X * abs(slope)
                compared += 1
                line += f" {ref:.5g} {bound:.3g}"
                if abs(a - ref) > bound:
                    failures.append(f"time {name}: a/a_w = {a:.4g}, reference {ref:.4g} (bound {bound:.3g})")
        print(line + f" {st} {k if k is not None else '-'}")
    if compared < 10:
        failures.append(f"only {compared} converged times on the lower branch (at least 10 needed)")
    if nucleation is None:
        failures.append("no step has status 'nucleation': the loss of equilibrium was not found")
    else:
        t, X = nucleation
        print(f"nucleation reported at time {t:g} (X = {X:.5g}); reference fold X = {FOLD_X}")
        if X < FOLD_X * (1 - 0.015):
            failures.append(f"nucleation at X = {X:.5g}, before the fold {FOLD_X} - 1.5 %")
        before = [s for s in stable if s[0] < t]
        if not before or before[-1][1] > FOLD_X * (1 + 0.015):
            failures.append("the last converged step before the nucleation is beyond the fold + 1.5 %")
        usable = [s for s in before if s[3] is not None and s[3] > 0]
        # The patch's stiffness changes where its node sets do (a node joins the slipping
        # patch or passes d_c): with steps finer than that, the last two converged steps can
        # share it. Then the latest earlier step with a larger one is the second point.
        earlier = [s for s in usable[:-1] if usable and s[3] > usable[-1][3] * (1 + 1e-9)]
        if usable and earlier:
            (t1, _, _, k1), (t2, _, a2, k2) = earlier[-1], usable[-1]
            tFold = t2 + k2 ** 2 * (t2 - t1) / (k1 ** 2 - k2 ** 2)
            XFold = math.sqrt(4 * alpha * tFold) / aw
            print(f"fold from the patch stiffness: t = {tFold:.5g} s, X = {XFold:.5g} "
                  f"({100 * (XFold / FOLD_X - 1):+.2f} % from {FOLD_X}); a/a_w there "
                  f"{a2:.4g} (reference {FOLD_A})")
            if not abs(XFold / FOLD_X - 1) <= 0.015:
                failures.append(f"the fold extrapolated from the patch stiffness is at X = {XFold:.5g}")
        else:
            failures.append("no two converged steps with different patch stiffnesses before the "
                            "nucleation")
    for f in failures:
        print("FAIL: " + f)
    if args.check and failures:
        sys.exit(1)


if __name__ == "__main__":
    main()
