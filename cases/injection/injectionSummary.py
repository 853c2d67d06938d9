#!/usr/bin/python3
"""The injection case's numbers per written time, and (--check) its physical checks.

Usage: injectionSummary.py CASE_DIR [--check] [--fracture fault]

Reads CASE_DIR/<time>/fractures/<fracture>.dat (columns by name, with pressure and
sigmaNEffective: README.md, "frictionSolver") and a few numbers of the case's dictionaries
(the friction coefficient, the well's position and rate, the storage and transmissivity, the
hydrostatic gradient), so that an edited case is summarised with its own values.

Per time: the pressure change at the well's node, Δp = p − p₀ (p₀ = ρ_f g · depth, the
initial state); the slipping nodes, their area (each node's share of a Delaunay triangulation
of the fault's nodes in its plane: a third of each triangle), the equivalent radius
R = √(area/π), R over the diffusion length √(4αt), the distance of the farthest slipping
node from the well, the largest slip; the largest |Δp| beyond 500 m from the well, and the
largest difference between Δp and the closed form of a fault without edges,
Δp* E₁(r²/4αt) with Δp* = Q/(4πκ), over the nodes 3h to 400 m from the well (h the median
distance from a node to its nearest neighbour).

The reference: a circular rupture driven by a rate injection on a fault under uniform stress
slips over r < λ √(4αt); far from being critically stressed (T = (μ σ'₀ − τ₀)/(μ Δp*) ≳ 1)
the pressure over the rupture is Δp* (ln(4αt/r²) − γ), and the zero stress-intensity
condition of a circular shear crack (ν = 0, the load axisymmetric) gives
λ = ½ exp((2 − γ − T)/2), γ = 0.5772 (Euler's constant). T is taken at the well's depth.

--check (exit 1 with the failures listed) asserts what the physics requires:
  * every step converged (the table's status line);
  * before any slip, σ_n and |τ| are the in-situ state's (the first time, all nodes stuck:
    σ_n, |τ| from the tables equal σ⁰ n·n and |σ⁰ n − (n·σ⁰ n) n| of constant/effects' stress
    to 1e-6 relative), so gravity and the in-situ stress balance;
  * the pressure change at the well's node rises at every step;
  * far from the well (beyond 500 m) Δp is the closed form's (tiny there) to 1e-2 Δp*
    (12 kPa in the case, against the 0.14 MPa of the injected volume spread evenly over the
    fault at two days: the front has not arrived), at the times before the closed form
    reaches 1e-3 Δp* at the fault's nearest edge (later the pressure piles up against the
    edges, which let no fluid through);
  * Coulomb at every node: |τ| = μ |σ'_n| at slipping nodes to 1e-7 relative, |τ| ≤ μ |σ'_n|
    (1 + 1e-7) elsewhere;
  * slip starts when the Coulomb stress change reaches the margin: at the last time before
    any slip μ Δp < μ |σ'_n0| − |τ0| at every node, and at the first time with slip at least
    one slipping node has μ Δp ≥ its margin (before slip, ΔCFS = μ Δp: the rock's stress
    does not change);
  * the slipping area never shrinks, and grows from the first to the last time with slip;
  * the slipping nodes lie in the pressurised region: Δp ≥ 25 % of the pressure change that
    alone would make each of them slip (the rest is the stress shed by the slip around them),
    and none is farther from the well than the diffusion length √(4αt);
  * the slip is a normal fault's: the hanging wall (the side above the fault) moves down dip.
"""
import argparse
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402

EULER_GAMMA = 0.5772156649015329


def stripComments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def number(case, file, pattern, what):
    path = os.path.join(case, file)
    m = re.search(pattern, stripComments(open(path).read()))
    if not m:
        raise SystemExit(f"{path}: cannot find {what}")
    return m.groups() if len(m.groups()) > 1 else m.group(1)


def readTable(path):
    lines = open(path).read().splitlines()
    names = lines[0][1:].split()
    for key in ("x", "y", "z", "sigmaN", "tauMagnitude", "pressure", "sigmaNEffective", "state"):
        if key not in names:
            raise SystemExit(f"{path}:1: no column '{key}'")
    status = next((l[1:].strip() for l in lines[1:] if l.startswith("# status")), "")
    rows = [l.split() for l in lines if l and not l.startswith("#")]
    table = {n: np.array([float(r[i]) for r in rows]) for i, n in enumerate(names) if n != "state"}
    table["state"] = np.array([r[names.index("state")] for r in rows])
    table["status"] = status
    return table


def exponentialIntegralE1(x):
    """E1(x), x > 0: its series below 1, its continued fraction (Lentz) above."""
    if x <= 1:
        total, term = 0.0, 1.0
        for k in range(1, 60):
            term *= -x / k
            total -= term / k
        return -EULER_GAMMA - math.log(x) + total
    b, c, d = x + 1, 1e300, 1 / (x + 1)
    h = d
    for i in range(1, 200):
        a = -i * i
        b += 2
        d = 1 / (a * d + b)
        c = b + a / c
        h *= c * d
        if abs(c * d - 1) < 1e-16:
            break
    return h * math.exp(-x)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case")
    ap.add_argument("--fracture", default="fault")
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args()
    case = a.case

    mu = float(number(case, "constant/fractureProperties",
                      r"frictionCoefficient\s+([^;\s]+)\s*;", "frictionCoefficient"))
    well = np.array([float(v) for v in number(
        case, "constant/effects", r"position\s*\(\s*(\S+)\s+(\S+)\s+(\S+)\s*\)", "the well")])
    rate = float(number(case, "constant/effects", r"\brate\s+([^;\s]+)\s*;", "the rate"))
    storage = float(number(case, "constant/effects", r"\bstorage\s+([^;\s]+)\s*;", "storage"))
    kappa = float(number(case, "constant/effects", r"\btransmissivity\s+([^;\s]+)\s*;",
                         "transmissivity"))
    rhoFG = -float(number(case, "constant/effects",
                          r"initial\s*\{[^}]*gradient\s+([^;\s]+)\s*;", "initial's gradient"))
    stress = number(case, "constant/effects",
                    r"inSitu\s*\{[^}]*gradient\s*\(([^)]*)\)", "inSitu's gradient")
    gradient = np.array([float(v) for v in stress.split()])  # sxx syy szz sxy syz sxz per m
    alpha = kappa / storage
    dpStar = rate / (4 * math.pi * kappa)

    times = sorted((d for d in os.listdir(case)
                    if re.fullmatch(r"[0-9.]+(e[-+]?[0-9]+)?", d) and float(d) > 0
                    and os.path.isfile(os.path.join(case, d, "fractures", a.fracture + ".dat"))),
                   key=float)
    if not times:
        raise SystemExit(f"{case}: no time folder with fractures/{a.fracture}.dat")
    tables = [readTable(os.path.join(case, t, "fractures", a.fracture + ".dat")) for t in times]

    first = tables[0]
    pos = np.column_stack([first["x"], first["y"], first["z"]])
    normal = np.array([first["nx"][0], first["ny"][0], first["nz"][0]])
    normal /= np.linalg.norm(normal)
    e1 = np.cross(normal, [0.0, 0.0, 1.0])
    e1 = e1 / np.linalg.norm(e1) if np.linalg.norm(e1) > 1e-12 else np.array([1.0, 0, 0])
    e2 = np.cross(normal, e1)
    u, v = (pos - well) @ e1, (pos - well) @ e2
    tri = mtri.Triangulation(u, v)
    area = np.zeros(len(u))
    for i, j, k in tri.triangles:
        area[[i, j, k]] += 0.5 * abs((u[j] - u[i]) * (v[k] - v[i]) - (u[k] - u[i]) * (v[j] - v[i])) / 3
    r = np.hypot(u, v)
    iw = int(np.argmin(np.linalg.norm(pos - well, axis=1)))
    nearest = np.sort(np.hypot(u[:, None] - u[None, :], v[:, None] - v[None, :]), axis=1)[:, 1]
    h = float(np.median(nearest))
    depth = -pos[:, 2]
    p0 = rhoFG * depth
    tip = first["state"] == "tip"

    # In-situ tractions on the fault (σ⁰ = gradient · z, the nodes' own normals).
    s = np.outer(pos[:, 2], gradient)  # per node: sxx syy szz sxy syz sxz
    sig = np.stack([np.stack([s[:, 0], s[:, 3], s[:, 5]], 1), np.stack([s[:, 3], s[:, 1], s[:, 4]], 1),
                    np.stack([s[:, 5], s[:, 4], s[:, 2]], 1)], 1)
    normals = np.column_stack([first["nx"], first["ny"], first["nz"]])
    traction = np.einsum("nij,nj->ni", sig, normals)
    sigmaN0 = np.einsum("ni,ni->n", traction, normals)
    tau0 = np.linalg.norm(traction - sigmaN0[:, None] * normals, axis=1)
    margin = mu * (-(sigmaN0 + p0)) - tau0  # μ|σ'_n0| − |τ0| [Pa]
    T = margin[iw] / (mu * dpStar)
    lam = 0.5 * math.exp((2 - EULER_GAMMA - T) / 2)

    print(f"fault '{a.fracture}': {len(u)} nodes ({int(tip.sum())} on the tip line), area "
          f"{area.sum():.4g} m2, node spacing h {h:.3g} m; well node at "
          f"({pos[iw][0]:.4g} {pos[iw][1]:.4g} {pos[iw][2]:.5g}), {np.linalg.norm(pos[iw] - well):.3g} m "
          f"from the well")
    print(f"mu {mu:g}, alpha {alpha:.4g} m2/s, dp* = Q/(4 pi kappa) {dpStar / 1e6:.4g} MPa; at the "
          f"well's depth: margin mu|sigma'_n0| - |tau0| {margin[iw] / 1e6:.4g} MPa, slip at "
          f"dp = {margin[iw] / mu / 1e6:.4g} MPa; T {T:.4g}, lambda(T) {lam:.3g}")
    print("time[s]  days  dpWell[MPa]  slipNodes  slipArea[m2]  R[m]  R/sqrt(4at)  rSlipMax[m]  "
          "maxSlip[mm]  maxDpBeyond500m[MPa]  closedFormError/dp*")
    failures = []
    rEdge = float(r[tip].min())  # the nearest point of the fault's edge (tip line) [m]

    def closedForm(distance, time):
        return dpStar * exponentialIntegralE1(distance * distance / (4 * alpha * time))
    checkedFar, worstFar = 0, 0.0
    previous, prevSet, lastStuck, firstSlip = None, set(), None, None
    for t, tab in zip(times, tables):
        time = float(t)
        p = tab["pressure"]
        dp = p - p0
        slip = tab["state"] == "slip"
        A = float(area[slip].sum())
        R = math.sqrt(A / math.pi)
        L = math.sqrt(4 * alpha * time)
        rMax = float(r[slip].max()) if slip.any() else 0.0
        far = r > 500
        ring = (r >= 3 * h) & (r <= 400)
        closed = np.array([closedForm(ri, time) for ri in r[ring]])
        cfErr = float(np.abs(dp[ring] - closed).max() / dpStar) if ring.any() else float("nan")
        print(f"{t}  {time / 86400:.4g}  {dp[iw] / 1e6:.4g}  {int(slip.sum())}  {A:.4g}  {R:.4g}  "
              f"{R / L:.3g}  {rMax:.4g}  {tab['slipMagnitude'].max() * 1e3:.4g}  "
              f"{np.abs(dp[far]).max() / 1e6 if far.any() else float('nan'):.3g}  {cfErr:.3g}")
        # The checks.
        if not tab["status"].startswith("status converged"):
            failures.append(f"time {t}: {tab['status']}")
        if previous is not None and not dp[iw] > previous["dpWell"]:
            failures.append(f"time {t}: dp at the well {dp[iw]:.6g} Pa did not rise "
                            f"(was {previous['dpWell']:.6g})")
        # Far from the well, while the front has not reached the fault's edges (no-flow: the
        # pressure then piles up there), Δp is the closed form's, tiny there.
        if far.any() and closedForm(rEdge, time) <= 1e-3 * dpStar:
            farErr = max(abs(dp[i] - closedForm(r[i], time)) for i in np.flatnonzero(far))
            checkedFar += 1
            worstFar = max(worstFar, farErr)
            if farErr > 1e-2 * dpStar:
                failures.append(f"time {t}: dp beyond 500 m from the well differs from the closed "
                                f"form by {farErr:.4g} Pa, more than 1e-2 dp* = {1e-2 * dpStar:.4g} Pa")
        on = ~tip
        tau, bound = tab["tauMagnitude"][on], mu * -tab["sigmaNEffective"][on]
        sl = slip[on]
        if sl.any() and np.abs(tau[sl] - bound[sl]).max() > 1e-7 * np.abs(bound[sl]).max():
            failures.append(f"time {t}: |tau| - mu|sigma'_n| up to "
                            f"{np.abs(tau[sl] - bound[sl]).max():.3g} Pa at slipping nodes")
        if (tau[~sl] > bound[~sl] * (1 + 1e-7)).any():
            failures.append(f"time {t}: |tau| > mu|sigma'_n| at a node that does not slip")
        cur = set(np.flatnonzero(slip))
        if not slip.any():
            lastStuck = (t, dp)
        elif firstSlip is None:
            firstSlip = (t, dp, slip)
        if previous is not None and A < previous["area"]:
            failures.append(f"time {t}: the slipping area fell from {previous['area']:.6g} to {A:.6g} m2")
        if prevSet - cur:
            print(f"  note: {len(prevSet - cur)} node(s) that slipped at the previous time do not now")
        if slip.any():
            need = margin[slip] / mu
            if (dp[slip] < 0.25 * need).any():
                failures.append(f"time {t}: a slipping node has dp below 25 % of the dp that alone "
                                "makes it slip (outside the pressurised region)")
            if rMax > L:
                failures.append(f"time {t}: a node {rMax:.4g} m from the well slips, beyond the "
                                f"diffusion length {L:.4g} m")
            # Normal faulting: the hanging wall (above the fault) moves down relative to the
            # footwall. The jump is Ω⁺ minus Ω⁻ and n_Γ points from Ω⁺ to Ω⁻, so Ω⁺ is the
            # hanging wall when n_Γ points down: then slipZ < 0; otherwise slipZ > 0.
            sign = 1.0 if normal[2] < 0 else -1.0
            down = sign * tab["slipZ"][slip] < 0
            if not down.all():
                failures.append(f"time {t}: {int((~down).sum())} slipping node(s) move the hanging "
                                "wall up (not a normal fault's slip)")
        previous = {"dpWell": dp[iw], "area": A}
        prevSet = cur

    # The in-situ state before any slip, and the onset of slip.
    if tables[0]["state"][~tip].tolist().count("stick") == int((~tip).sum()):
        on = ~tip
        errN = np.abs(tables[0]["sigmaN"][on] - sigmaN0[on]).max() / np.abs(sigmaN0[on]).max()
        errT = np.abs(tables[0]["tauMagnitude"][on] - tau0[on]).max() / np.abs(sigmaN0[on]).max()
        print(f"in-situ check at t = {times[0]}: sigma_n and |tau| against sigma0 within "
              f"{max(errN, errT):.2e} (relative to max |sigma_n0|)")
        if max(errN, errT) > 1e-6:
            failures.append(f"time {times[0]}: the tractions differ from the in-situ state by "
                            f"{max(errN, errT):.3g} (relative)")
    else:
        failures.append(f"time {times[0]}: the fault slips at the first time: the onset is not "
                        "resolved (start with a shorter deltaT)")
    if firstSlip is None:
        failures.append("nothing slips by the last time")
    elif lastStuck is not None:
        t0, dp0 = lastStuck
        t1, dp1, slip1 = firstSlip
        cfs0 = (mu * dp0 - margin)[~tip].max()
        cfs1 = (mu * dp1 - margin)[slip1].max()
        print(f"onset: at t = {t0} every node has mu dp - margin <= {cfs0 / 1e6:.4g} MPa (stuck); "
              f"at t = {t1} the slipping nodes reach mu dp - margin up to {cfs1 / 1e6:.4g} MPa")
        if cfs0 >= 0:
            failures.append(f"time {t0}: mu dp reached the margin ({cfs0:.4g} Pa over) but nothing slips")
        if cfs1 < 0:
            failures.append(f"time {t1}: slip started before mu dp reached the margin at any "
                            f"slipping node ({cfs1:.4g} Pa short)")
    print(f"far field: dp beyond 500 m within {worstFar:.3g} Pa of the closed form at "
          f"{checkedFar} time(s) "
          f"(those before the closed form reaches 1e-3 dp* at the fault's nearest edge, "
          f"{rEdge:.4g} m from the well)")
    if checkedFar == 0:
        failures.append("the far field was checked at no time (the first step too long)")
    slipAreas = [float(area[tab["state"] == "slip"].sum()) for tab in tables]
    if firstSlip is not None and not slipAreas[-1] > slipAreas[times.index(firstSlip[0])]:
        failures.append("the slipping area did not grow after the onset")
    if a.check:
        if failures:
            print("FAIL: " + "; ".join(failures))
            return 1
        print("PASS: every check above (README.md of the case, 'What is checked')")
    return 0


if __name__ == "__main__":
    sys.exit(main())
