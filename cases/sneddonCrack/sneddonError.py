#!/usr/bin/env python3
"""Sneddon's pressurised crack: the computed opening against the exact one.

A straight crack of half-length a in an unbounded plane-strain body, its faces loaded by a
fluid pressure p, under a remote normal stress sigma_n_inf (negative in compression) and no
remote shear, opens where the net pressure dp = p + sigma_n_inf is positive:

    g(x) = 4 (1 - nu^2) dp / E * sqrt(a^2 - x^2)     (plane stress: 4 dp / E * sqrt(...)),

with tau = 0 and sigma_n = -p on the open faces. A remote shear tau_inf (-tau) then slides the
open (traction-free) faces as the mode II crack does: |s(x)| = 4 (1 - nu^2) |tau_inf| / E *
sqrt(a^2 - x^2). Reads the fracture table of the latest time
folder (or -time), interpolates the opening on each crack element (P1: linear, P2: quadratic
through the midpoint, from system/frictionSolution's elementOrder) and integrates the error
with 6 Gauss points per element. Prints, one per line, "name value":

    relL2Error       ||g_h - g||_L2 / ||g||_L2 over the crack
    maxOpeningError  max over the nodes of |g_h - g| / max g
    maxTau           max |tau| / p over the open nodes
    maxSigmaNError   max |sigma_n + p| / p over the open nodes
    minOpening       min g_h / max g (negative: the faces overlap)
    slipRelL2Error   with -tau: || |s_h| - |s| ||_L2 / || s ||_L2
    states           the number of nodes in each state

--maxError E and --maxTraction T make the exit code 1 when relL2Error > E or when maxTau or
maxSigmaNError > T.
"""
import argparse
import math
import os
import re
import sys


def read_number(path, key):
    text = open(path).read()
    text = re.sub(r"//.*", "", text)
    m = re.search(r"(^|\s)" + key + r"\s+([^;\s]+)\s*;", text)
    return m.group(2) if m else None


def latest_time(case):
    best = None
    for name in os.listdir(case):
        try:
            t = float(name)
        except ValueError:
            continue
        if t > 0 and os.path.isfile(os.path.join(case, name, "fractures", "crack.dat")):
            if best is None or t > best[0]:
                best = (t, name)
    if best is None:
        sys.exit("sneddonError.py: no time folder with fractures/crack.dat in " + case)
    return best[1]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-case", default=".")
    ap.add_argument("-time", default=None)
    ap.add_argument("-p", type=float, default=1e6, help="fracture pressure p [Pa]")
    ap.add_argument("-sigmaN", type=float, default=0.0,
                    help="remote normal stress on the crack plane [Pa], negative in compression")
    ap.add_argument("-tau", type=float, default=None,
                    help="remote shear on the crack's plane [Pa] (the slip is then checked)")
    ap.add_argument("--maxError", type=float, default=None)
    ap.add_argument("--maxTraction", type=float, default=None)
    args = ap.parse_args()

    case = args.case
    props = os.path.join(case, "constant", "mechanicalProperties")
    E = float(read_number(props, "E"))
    nu = float(read_number(props, "nu"))
    plane_stress = (read_number(props, "planeStress") or "no") in ("yes", "on", "true")
    order = int(read_number(os.path.join(case, "system", "frictionSolution"), "elementOrder") or 1)
    time = args.time or latest_time(case)
    path = os.path.join(case, time, "fractures", "crack.dat")

    with open(path) as f:
        header = f.readline().split()[1:]
        rows = [line.split() for line in f if line.strip() and not line.startswith("#")]
    col = {name: i for i, name in enumerate(header)}
    for needed in ("s", "x", "slip", "sigmaN", "tau", "opening", "state"):
        if needed not in col:
            sys.exit("sneddonError.py: " + path + " has no column '" + needed + "'")
    s = [float(r[col["s"]]) for r in rows]
    x = [float(r[col["x"]]) for r in rows]
    g = [float(r[col["opening"]]) for r in rows]
    a = (max(x) - min(x)) / 2
    centre = (max(x) + min(x)) / 2
    dp = args.p + args.sigmaN
    factor = (4.0 if plane_stress else 4.0 * (1 - nu * nu)) * max(dp, 0.0) / E

    def exact(xx):
        r = a * a - (xx - centre) ** 2
        return factor * math.sqrt(r) if r > 0 else 0.0

    # Gauss-Legendre, 6 points on [-1, 1].
    gx = [-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
          0.2386191860831969, 0.6612093864662645, 0.9324695142031521]
    gw = [0.1713244923791704, 0.3607615730481386, 0.4679139345726910,
          0.4679139345726910, 0.3607615730481386, 0.1713244923791704]
    step = 2 if order == 2 else 1
    if (len(rows) - 1) % step:
        sys.exit("sneddonError.py: %d nodes do not make P%d elements" % (len(rows), order))

    def rel_l2(values, exact_at):
        err2 = ref2 = 0.0
        for e in range(0, len(rows) - 1, step):
            x0, x1 = x[e], x[e + step]
            for t, w in zip(gx, gw):
                xi = (t + 1) / 2  # 0..1 along the element
                if order == 2:
                    v = (values[e], values[e + 1], values[e + 2])
                    vh = (v[0] * (1 - xi) * (1 - 2 * xi) + v[1] * 4 * xi * (1 - xi)
                          + v[2] * xi * (2 * xi - 1))
                else:
                    vh = values[e] * (1 - xi) + values[e + 1] * xi
                xx = x0 + xi * (x1 - x0)
                weight = w * abs(x1 - x0) / 2
                err2 += weight * (vh - exact_at(xx)) ** 2
                ref2 += weight * exact_at(xx) ** 2
        return math.sqrt(err2 / ref2) if ref2 > 0 else math.sqrt(err2)
    gmax = factor * a if factor > 0 else max(max(g), 1e-300)
    states = {}
    max_tau = max_sn = 0.0
    open_nodes = 0
    for r in rows:
        state = r[col["state"]]
        states[state] = states.get(state, 0) + 1
        if state == "open":
            open_nodes += 1
            max_tau = max(max_tau, abs(float(r[col["tau"]])) / args.p)
            max_sn = max(max_sn, abs(float(r[col["sigmaN"]]) + args.p) / args.p)
    rel = rel_l2(g, exact)
    max_node = max(abs(gi - exact(xi)) for gi, xi in zip(g, x)) / gmax
    print("time             %s" % time)
    print("order            P%d" % order)
    print("crackNodes       %d" % len(rows))
    print("openNodes        %d" % open_nodes)
    print("relL2Error       %.6g" % rel)
    print("maxOpeningError  %.6g" % max_node)
    print("maxTau           %.6g" % max_tau)
    print("maxSigmaNError   %.6g" % max_sn)
    print("minOpening       %.6g" % (min(g) / gmax))
    if args.tau is not None:
        slip = [abs(float(r[col["slip"]])) for r in rows]
        shear = (4.0 if plane_stress else 4.0 * (1 - nu * nu)) * abs(args.tau) / E
        print("slipRelL2Error   %.6g" % rel_l2(
            slip, lambda xx: shear * math.sqrt(max(a * a - (xx - centre) ** 2, 0.0))))
    print("states           " + " ".join("%s %d" % kv for kv in sorted(states.items())))
    bad = []
    if args.maxError is not None and not rel <= args.maxError:
        bad.append("relL2Error %.4g > %.4g" % (rel, args.maxError))
    if args.maxTraction is not None and not (max_tau <= args.maxTraction
                                             and max_sn <= args.maxTraction):
        bad.append("traction on open faces %.3g, %.3g > %.3g" % (max_tau, max_sn, args.maxTraction))
    if bad:
        print("FAILED: " + "; ".join(bad))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
