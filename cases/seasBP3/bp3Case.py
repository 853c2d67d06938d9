#!/usr/bin/python3
"""Writes the dictionaries of SEAS benchmark BP3-QD (Erickson, Jiang, Dunham et al. 2023,
BSSA 113, 499-523; the specification "SEAS Benchmark Problems BP3-QD and BP3-FD", 2021) for a
dip and a sense of motion: constant/mechanicalProperties, constant/effects,
constant/fractureProperties, 0/D, system/controlDict, system/frictionSolution, system/meshDict.

Usage: bp3Case.py [--dip 60] [--sense thrust|normal] [--years 1500] [--deltaT-years 5]
                  [--tolerance 1e-8] [--order 1|2]

Every number below is the specification's (its Table 1, eqs. 4, 18, 19, 24-26), converted to
libfriction's conventions (docs/method.md §2): y up, the fault walked down-dip from its trace,
so t_Gamma points down-dip and the hanging wall (x >= z cot(dip)) is Omega+; slip and shear
count positive along t_Gamma there, so the outputs in SEAS's convention (faultOutput) take
positiveSlip = up-dip.
"""
import argparse
import math

p = argparse.ArgumentParser()
p.add_argument("--dip", type=float, default=60.0)
p.add_argument("--sense", choices=["thrust", "normal"], default="thrust")
p.add_argument("--years", type=float, default=1500.0)
p.add_argument("--deltaT-years", type=float, default=5.0)
p.add_argument("--tolerance", type=float, default=1e-8)
p.add_argument("--order", type=int, choices=[1, 2], default=1)
args = p.parse_args()

year = 365 * 24 * 3600.0  # the specification's (and tandem's) year: 365 days
rho, cs, nu = 2670.0, 3464.0, 0.25
G = rho * cs**2  # 32.04 GPa
lam = 2 * nu * G / (1 - 2 * nu)
a0, amax, b, L, f0, V0 = 0.010, 0.025, 0.015, 0.008, 0.6, 1e-6
H, h, Wf = 15e3, 3e3, 40e3
sigma0 = 50e6
Vp = 1e-9  # |V_p| = |V_L| = |V_init|
eta = G / (2 * cs)
# eq. 24: the uniform initial shear, the steady state at V_init with a = a_max, plus eta V.
tau0 = sigma0 * amax * math.asinh(Vp / (2 * V0) * math.exp((f0 + b * math.log(V0 / Vp)) / amax)) \
    + eta * Vp

psi = math.radians(args.dip)
c, s = math.cos(psi), math.sin(psi)
sense = 1.0 if args.sense == "thrust" else -1.0
# t_Gamma (down-dip) and n_Gamma = (t_y, -t_x), from Omega+ (hanging wall) to Omega-.
t = (c, -s)
n = (t[1], -t[0])
# Thrust: the hanging wall moves up-dip (-t_Gamma): a negative slip, resisted by a positive tau
# (docs/method.md §2). sigma = -sigma0 I + tau (n t + t n) has n.sigma.n = -sigma0 and
# t.sigma.n = tau.
tau = sense * tau0
sxx = -sigma0 + tau * 2 * n[0] * t[0]
syy = -sigma0 + tau * 2 * n[1] * t[1]
sxy = tau * (n[0] * t[1] + t[0] * n[1])
upDip = (-c, s)
# eq. 4: the two sides move as rigid bodies by -/+ (V_p t / 2) up-dip (hanging wall up for thrust).
end = args.years * year
half = sense * Vp * end / 2
right = (half * upDip[0], half * upDip[1])
left = (-right[0], -right[1])
creepDirection = (sense * upDip[0], sense * upDip[1])

head = lambda obj, cls="dictionary": (
    "FoamFile { version 2.0; format ascii; class %s; object %s; }\n"
    "// Written by bp3Case.py --dip %g --sense %s (SEAS BP3-QD); edit that script, not this file.\n"
    % (cls, obj, args.dip, args.sense))
g = lambda x: repr(float(x))

files = {}
files["constant/mechanicalProperties"] = head("mechanicalProperties") + (
    "// rho = 2670 kg/m^3, c_s = 3464 m/s, nu = 0.25: mu = rho c_s^2, lambda = mu.\n"
    "lambda %s;\nmu     %s;\nplaneStress no;\n" % (g(lam), g(G)))
files["constant/effects"] = head("effects") + (
    "// The prestress on the fault: sigma_n = -50 MPa and |tau| = tau0 = %.6f MPa\n"
    "// (eq. 24), uniform; it does not load the body (a uniform in-situ stress).\n"
    "prestress { type initialStress; stress (%s %s %s); }\n" % (tau0 / 1e6, g(sxx), g(syy), g(sxy)))
files["constant/fractureProperties"] = head("fractureProperties") + (
    "// 0 <= x_d <= Wf = 40 km: rate-and-state friction, a(x_d) by eq. 18 (x_d is the arclength).\n"
    "fault\n{\n    law                 rateState;\n"
    "    a                   { type arclength; table ((0 %g) (%g %g) (%g %g) (%g %g)); }\n"
    "    b                   %g;\n    characteristicSlip  %g;\n    referenceFriction   %g;\n"
    "    referenceSlipRate   %g;\n    initialSlipRate     %g;\n    shearWaveSpeed      %g;\n}\n"
    "// x_d > Wf: creeps at V_L = 1e-9 m/s (eq. 19), the hanging wall moving %s.\n"
    "creep\n{\n    law         creep;\n    slipRate    %g;\n    direction   (%s %s);\n}\n"
    % (a0, H, a0, H + h, amax, Wf * 1.01, amax, b, L, f0, V0, Vp, cs,
       "up-dip" if sense > 0 else "down-dip", Vp, g(creepDirection[0]), g(creepDirection[1])))
files["0/D"] = head("D", "pointVectorField") + (
    "// eq. 4: the sides move as rigid bodies, -/+ V_p t/2 along the dip, linearly in time;\n"
    "// the free surface and the bottom are traction-free.\n"
    "dimensions [0 1 0 0 0 0 0];\ninternalField uniform (0 0);\nboundaryField\n{\n"
    "    top    { type free; }\n    bottom { type free; }\n"
    "    right  { type fixedDisplacement; value table ((0 (0 0)) (%s (%s %s))); }\n"
    "    left   { type fixedDisplacement; value table ((0 (0 0)) (%s (%s %s))); }\n}\n"
    % (g(end), g(right[0]), g(right[1]), g(end), g(left[0]), g(left[1])))
stations = "".join("        fltst_dp%03d %g;\n" % (d * 10, d * 1000)
                   for d in (0, 2.5, 5, 7.5, 10, 12.5, 15, 17.5, 20, 25, 30, 35))
surface = "".join("        srfst_fn%s (%s 0);\n" % (name, x) for name, x in
                  (("-32", "-32000"), ("-16", "-16000"), ("-08", "-8000"), ("-00", "-0.001"),
                   ("+00", "0.001"), ("+08", "8000"), ("+16", "16000"), ("+32", "32000")))
files["system/controlDict"] = head("controlDict") + (
    "application     frictionSolver;\nstartTime       0;\nendTime         %s;   // %g years\n"
    "deltaT          %s;   // %g years\nwriteControl    timeStep;\nwriteInterval   20;\n"
    "writePrecision  10;\n"
    "// The benchmark's outputs: stations on the fault and at the surface (every Runge-Kutta\n"
    "// step), profiles every 500 m to 40 km (every 5 years, every second while seismic: max\n"
    "// V >= 1e-3 m/s).\n"
    "faultOutput\n{\n    fracture        fault;\n    positiveSlip    (%s %s);   // up-dip: SEAS's sign\n"
    "    seismicSlipRate 1e-3;\n"
    "    ruptures        yes;   // rupture_<k>.dat: each event's rupture times and slip per node\n"
    "    stations\n    {\n%s    }\n"
    "    profiles        { from 0; to 40000; spacing 500; interval %s; seismicInterval 1; }\n"
    "    // The surface stations at x km (+00 and -00: a millimetre either side of the trace,\n"
    "    // on the hanging wall and the footwall); w positive downwards, as the benchmark's.\n"
    "    surfaceStations\n    {\n%s    }\n    verticalDown    yes;\n}\n"
    % (g(end), args.years, g(args.deltaT_years * year), args.deltaT_years, g(upDip[0]),
       g(upDip[1]), stations, g(5 * year), surface))
files["system/frictionSolution"] = head("frictionSolution") + (
    "elementOrder    %d;\nlinearSolver    cholmod;\n"
    "timeIntegration { type quasiDynamic; relativeTolerance %g; }\n"
    "control\n{\n    gammaRelative   1;\n"
    "    optimizer { type semismoothNewton; tolerance 1e-10; maxIterations 100; }\n}\n"
    % (args.order, args.tolerance))
files["system/meshDict"] = head("meshDict") + (
    "mesh        \"constant/mesh/bp3.msh\";\nfractures   (fault creep);   // joined at x_d = Wf: "
    "one node, fault's law\n")
for path, text in files.items():
    with open(path, "w") as f:
        f.write(text)
print("bp3Case.py: dip %g, %s, tau0 = %.6f MPa, eta = %.6g Pa s/m, %g years"
      % (args.dip, args.sense, tau0 / 1e6, eta, args.years))
