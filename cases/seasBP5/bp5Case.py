#!/usr/bin/python3
"""Writes the dictionaries of SEAS benchmark BP5-QD (Jiang, Erickson et al. 2022, JGR Solid
Earth 127, e2021JB023519; the specification "SEAS Benchmark Problems BP5-QD and BP5-FD",
2020) for libfriction: constant/mechanicalProperties, constant/effects,
constant/fractureProperties and the fields it names (constant/bp5-*.dat), 0/D,
system/controlDict, system/frictionSolution, system/meshDict.

Usage: bp5Case.py [--years 1800] [--deltaT-years 10] [--tolerance 1e-8] [--order 1|2]

The numbers are the specification's, as tandem's BP5 example (TEAR-ERC/tandem,
examples/tandem/3d) states them. Coordinates are libfriction's (metres, z up): x along
strike (SEAS's x2), y across the fault (x1), depth = -z (x3). The fault is the rectangle
|x| <= 50 km, 0 <= depth <= 40 km of the plane y = 0, Omega+ the side y > 0 (splitFractureNodes
orients n_Gamma = (0, -1, 0)), which is also SEAS's + side: positive slip_2 is right-lateral.
"""
import argparse
import math

p = argparse.ArgumentParser()
p.add_argument("--years", type=float, default=1800.0)
p.add_argument("--deltaT-years", type=float, default=10.0)
p.add_argument("--tolerance", type=float, default=1e-8)
p.add_argument("--order", type=int, choices=[1, 2], default=1)
# How the right-hand side's dense S is stored (faultOperator's precision; README, "S in single
# precision"): auto (single from 2^22 entries), double or single.
p.add_argument("--precision", choices=["auto", "double", "single"], default="auto")
# The body's half-length along strike and depth (bp5.geo's X and Z): the creeping plane's
# field reaches them.
p.add_argument("--X", type=float, default=200e3)
p.add_argument("--Z", type=float, default=100e3)
args = p.parse_args()

year = 365 * 24 * 3600.0
rho, cs, nu = 2670.0, 3464.0, 0.25
G = rho * cs**2
lam = 2 * nu * G / (1 - 2 * nu)
eta = G / (2 * cs)
a0, amax, b, f0, V0 = 0.004, 0.04, 0.03, 0.6, 1e-6
sigma = 25e6
Vp, Vi = 1e-9, 0.01                  # plate rate; initial slip rate in the nucleation zone
L, Lnuc = 0.14, 0.13
hs, ht, H, l, w = 2e3, 2e3, 12e3, 60e3, 12e3
lf, Wf = 100e3, 40e3
psi0 = f0 + b * math.log(V0 / Vp)    # theta0 = L/V_p everywhere


def a_of(x, d):
    """a(x2, x3): a0 on the velocity-weakening patch, amax outside, linear in between."""
    s = abs(x)
    if hs + ht <= d <= hs + ht + H and s <= l / 2:
        return a0
    if d <= hs or d >= hs + 2 * ht + H or s >= l / 2 + ht:
        return amax
    r = max(abs(d - hs - ht - H / 2) - H / 2, s - l / 2) / ht
    return a0 + r * (amax - a0)


def nucleation(x, d):
    """The w x w patch at the velocity-weakening zone's left end."""
    return hs + ht <= d <= hs + ht + H and -l / 2 <= x <= -l / 2 + w


def tau0(x, d):
    """The shear under which the node slides at its V_init with theta0 = L/V_p."""
    a = a_of(x, d)
    V = Vi if nucleation(x, d) else Vp
    return sigma * a * math.asinh(V / (2 * V0) * math.exp(psi0 / a)) + eta * V


# The fields, on a 500 m grid of the rate-and-state rectangle (every node there of a mesh of
# h = 500 m multiples, P2 midpoints included, lies on a row). The rest of the plane y = 0 (the
# benchmark's creeping region, which has no state) takes the nearest row, on the rectangle's
# border: hence maxDistance 400 km.
step = 500.0
nx, nz = int(round(lf / step)), int(round(Wf / step))
rows = {"a": [], "L": [], "Vinit": [], "tau0": []}
for i in range(nx + 1):
    x = -lf / 2 + i * step
    for j in range(nz + 1):
        d = j * step
        xyz = "%g 0 %g" % (x, -d)
        rows["a"].append("%s %.17g" % (xyz, a_of(x, d)))
        rows["L"].append("%s %.17g" % (xyz, Lnuc if nucleation(x, d) else L))
        rows["Vinit"].append("%s %.17g" % (xyz, Vi if nucleation(x, d) else Vp))
        rows["tau0"].append("%s %.17g" % (xyz, tau0(x, d)))
# Where the fault creeps at V_p: the plane y = 0 beyond the rectangle (|x| > 50 km or depth >
# 40 km); 0 on the rectangle, whose nodes lie on rows. Rows every 500 m to 10 km from it (the
# outer nodes nearest to it are a cell away: their nearest row is an outer one), every 5 km
# farther, to the body's sides (X, 200 km by default) and bottom (Z, 100 km).
X, Z = args.X, args.Z
creep = []
for spacing, reach in ((500.0, 10e3), (5e3, None)):
    for i in range(int(round(2 * X / spacing)) + 1):
        x = -X + i * spacing
        for j in range(int(round(Z / spacing)) + 1):
            d = j * spacing
            inside = abs(x) <= lf / 2 and d <= Wf
            near = abs(x) <= lf / 2 + 10e3 and d <= Wf + 10e3
            if reach is not None and (not near or inside and spacing != step):
                continue
            if reach is None and near:
                continue
            creep.append("%g 0 %g %.17g" % (x, -d, 0.0 if inside else Vp))
rows["creep"] = creep
for name, r in rows.items():
    with open("constant/bp5-%s.dat" % name, "w") as f:
        f.write("# x y z %s on SEAS BP5-QD's fault, written by bp5Case.py\n" % name)
        f.write("\n".join(r) + "\n")


def field(name, maxDistance=2 * max(args.X, args.Z)):
    return '{ type points; file "constant/bp5-%s.dat"; maxDistance %g; }' % (name, maxDistance)


head = lambda obj, cls="dictionary": (
    "FoamFile { version 2.0; format ascii; class %s; object %s; }\n"
    "// Written by bp5Case.py (SEAS BP5-QD); edit that script, not this file.\n" % (cls, obj))
g = lambda x: repr(float(x))
end = args.years * year
files = {}
files["constant/mechanicalProperties"] = head("mechanicalProperties") + (
    "// rho = 2670 kg/m^3, c_s = 3464 m/s, nu = 0.25: mu = rho c_s^2, lambda = mu.\n"
    "lambda %s;\nmu     %s;\n" % (g(lam), g(G)))
files["constant/effects"] = head("effects") + (
    "// The fault's prestress: sigma_n = -25 MPa, and the shear under which each node slides at\n"
    "// its V_init with theta0 = L/V_p (tau0 from %.4f MPa on the velocity-weakening patch to\n"
    "// %.4f MPa outside; %.4f MPa in the nucleation zone), driving y > 0 along +x.\n"
    "prestress\n{\n    type        faultTraction;\n    fracture    fault;\n"
    "    normal      %s;\n    shear       %s;\n    direction   (1 0 0);\n}\n"
    % (tau0(0, 10e3) / 1e6, tau0(0, 30e3) / 1e6, tau0(-24e3, 10e3) / 1e6, g(-sigma),
       field("tau0")))
files["constant/fractureProperties"] = head("fractureProperties") + (
    "// Rate-and-state friction on the plane y = 0: on the 100 km x 40 km fault a = 0.004 on the\n"
    "// velocity-weakening patch (60 km x 12 km at 4-16 km depth), 0.04 outside, linear over\n"
    "// h_t = 2 km between; L = 0.13 m and V_init = %g m/s in the 12 km x 12 km nucleation zone\n"
    "// (x from -30 to -18 km), 0.14 m and V_p elsewhere. Beyond the 100 km x 40 km the fault\n"
    "// creeps at V_p along +x (creepSlipRate > 0 there).\n"
    "fault\n{\n    law                 rateState;\n    a                   %s;\n"
    "    b                   %g;\n    characteristicSlip  %s;\n    referenceFriction   %g;\n"
    "    referenceSlipRate   %g;\n    initialSlipRate     %s;\n    shearWaveSpeed      %g;\n"
    "    creepSlipRate       %s;\n    creepDirection      (1 0 0);\n}\n"
    % (Vi, field("a"), b, field("L"), f0, V0, field("Vinit"), cs, field("creep", 4e3)))
half = Vp * end / 2
files["0/D"] = head("D", "pointVectorField") + (
    "// The far sides move as rigid bodies along strike, +/- V_p t / 2 (y > 0: +x), linearly in\n"
    "// time; the free surface and the bottom are traction-free (tandem's BP5 example). The\n"
    "// fault plane y = 0 cuts the whole body: beyond the 100 km x 40 km it creeps at V_p.\n"
    "dimensions [0 1 0 0 0 0 0];\ninternalField uniform (0 0 0);\nboundaryField\n{\n"
    "    top    { type free; }\n    bottom { type free; }\n"
    "    plus   { type fixedDisplacement; value table ((0 (0 0 0)) (%s (%s 0 0))); }\n"
    "    minus  { type fixedDisplacement; value table ((0 (0 0 0)) (%s (%s 0 0))); }\n}\n"
    % (g(end), g(half), g(end), g(-half)))
stations = [("-36", "+00", -36, 0), ("-16", "+00", -16, 0), ("+00", "+00", 0, 0),
            ("+16", "+00", 16, 0), ("+36", "+00", 36, 0), ("-24", "+10", -24, 10),
            ("-16", "+10", -16, 10), ("+00", "+10", 0, 10), ("+16", "+10", 16, 10),
            ("+00", "+22", 0, 22)]
stationText = "".join("        fltst_strk%sdp%s (%g 0 %g);\n" % (s, d, x * 1e3, -z * 1e3)
                      for s, d, x, z in stations)
files["system/controlDict"] = head("controlDict") + (
    "application     frictionSolver;\nstartTime       0;\nendTime         %s;   // %g years\n"
    "deltaT          %s;   // %g years\nwriteControl    timeStep;\nwriteInterval   10;\n"
    "writePrecision  10;\n"
    "// The benchmark's fault stations (strike x2 and depth x3 in km), every Runge-Kutta step.\n"
    "faultOutput\n{\n    fracture        fault;\n    strike          (1 0 0);   // SEAS's x2\n"
    "    seismicSlipRate 1e-3;\n"
    "    ruptures        yes;   // rupture_<k>.dat: each event's rupture times and slip per node\n"
    "    stations\n    {\n%s    }\n}\n"
    % (g(end), args.years, g(args.deltaT_years * year), args.deltaT_years, stationText))
files["system/frictionSolution"] = head("frictionSolution") + (
    "elementOrder    %d;\nlinearSolver    cholmod;\n"
    "timeIntegration { type quasiDynamic; relativeTolerance %g;%s }\n"
    "control\n{\n    gammaRelative   1;\n"
    "    optimizer { type semismoothNewton; tolerance 1e-10; maxIterations 100; }\n}\n"
    % (args.order, args.tolerance,
       "" if args.precision == "auto"
       else " faultOperator { type auto; precision %s; }" % args.precision))
files["system/meshDict"] = head("meshDict") + (
    "mesh        \"constant/mesh/bp5.msh\";\nfractures   (fault);\n")
for path, text in files.items():
    with open(path, "w") as f:
        f.write(text)
print("bp5Case.py: tau0 %.4f MPa (velocity weakening), %.4f MPa (outside), %.4f MPa "
      "(nucleation), eta = %.6g Pa s/m, %g years"
      % (tau0(0, 10e3) / 1e6, tau0(0, 30e3) / 1e6, tau0(-24e3, 10e3) / 1e6, eta, args.years))
