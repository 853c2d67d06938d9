#!/usr/bin/env python3
"""A well on a 3D fault, and the same case turned as a whole, give the same answer.

tests/regression/cases/wellInBox (a box held on every face, a planar fault dipping 60 degrees
inside, off the origin, a uniform in-situ stress by initialStress, a little gravity, a
faultPressure with p0 = 10 MPa and a well injecting a constant rate at the fault's centre) is
meshed once by gmsh; the turned copies have the same mesh with every node moved by a rotation
R (their $Nodes coordinates), and R applied to everything that has a direction: the in-situ
stress R sigma R^T, the gravity R g, the well's position R x_w. Each is run with the pressure
by the closed form (E1) and computed by diffusion on the fault's mesh. Checked:

 * at corresponding nodes (R^T x' = x) and both times: |slip|, |tau|, sigma_n, p, sigma'_n,
   ST, deltaCFS and the state are those of the unturned run, and the slip vector is R times
   its slip vector (up to the sign of the jump: n_Gamma' = +-R n_Gamma, chosen by the
   orientation rule of fracture/SignConventions.hpp); to TOL relative to each quantity's
   largest value. Why TOL = 1e-10: the runs differ only by the rounding of the turned
   coordinates and of the sums (1e-16 relative) and by the tangent basis of each node (the
   friction law is isotropic in the tangent plane); semismooth Newton ends on the same
   active set in both, so the answers are the same linear solves up to that rounding times
   the conditioning (measured: at most 1.2e-14, deltaCFS, a difference of larger numbers).
   1e-10 is the solver's own stopping tolerance (|D| <= 1e-10 |Sigma|,
   system/frictionSolution): a difference above it cannot be rounding, and any dependence on
   the frame (a wrong sign, a formula in fixed axes) shows at order 1;
 * in every table: slipStrike^2 + slipDip^2 = slipMagnitude^2 and tauStrike^2 + tauDip^2 =
   tauMagnitude^2 (both in the tangent plane), and the strike and dip vectors that the
   columns imply (the hanging wall's slip = slipStrike s + slipDip d) satisfy the README's
   rule: s horizontal, d pointing down the fault plane, d = s turned clockwise by 90 degrees
   seen from above;
 * for the rotation about z (the vertical kept): slipStrike, slipDip, tauStrike and tauDip
   themselves are the unturned run's (the hanging wall's slip and traction, whatever side
   n_Gamma points to; the angle 150 degrees makes n_Gamma point to the other side), and in
   both the hanging wall slips down dip (slipDip > 0, tauDip < 0: sigma_zz is the largest
   compression, a normal-faulting stress).

Usage: pressureInvariance.py BIN_DIR SOURCE_DIR WORK_DIR
"""
import math
import os
import re
import shutil
import subprocess
import sys

TOL = 1e-10
bin_dir, src, work = sys.argv[1:4]


def fail(message):
    print(f"FAIL [pressureInvariance]: {message}")
    sys.exit(1)


def rotation(axis, angle):
    """The matrix of the rotation by angle [rad] about axis (Rodrigues), as rows."""
    n = math.sqrt(sum(a * a for a in axis))
    x, y, z = (a / n for a in axis)
    c, s, C = math.cos(angle), math.sin(angle), 1 - math.cos(angle)
    return [[c + x * x * C, x * y * C - z * s, x * z * C + y * s],
            [y * x * C + z * s, c + y * y * C, y * z * C - x * s],
            [z * x * C - y * s, z * y * C + x * s, c + z * z * C]]


def apply(R, v):
    return [sum(R[i][j] * v[j] for j in range(3)) for i in range(3)]


def transpose(R):
    return [[R[j][i] for j in range(3)] for i in range(3)]


def matmul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def num(x):
    return repr(float(x))


# The unturned set-up (wellInBox's geometry: the fault's centre, where the well is).
SIGMA = [[-18e6, 2e6, 0.0], [2e6, -20e6, 0.0], [0.0, 0.0, -30e6]]  # [Pa]
GRAVITY = [0.0, 0.0, -9.81]  # [m/s2]
WELL = [100.0, -50.0, 80.0]  # [m]
IDENTITY = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
TURNS = {
    "base": IDENTITY,
    "aboutZ": rotation((0, 0, 1), math.radians(150)),
    "generic": rotation((1, 2, 3), 0.9),
}


def effects(R, model):
    s = matmul(matmul(R, SIGMA), transpose(R))
    g, w = apply(R, GRAVITY), apply(R, WELL)
    stress = " ".join(num(v) for v in (s[0][0], s[1][1], s[2][2], s[0][1], s[1][2], s[0][2]))
    flow = "model diffusion;" if model == "diffusion" else ""
    return f"""FoamFile
{{
    version 2.0;
    format ascii;
    class dictionary;
    object effects;
}}
gravity {{ type bodyForce; density 250; g ({" ".join(num(v) for v in g)}); }}
inSitu {{ type initialStress; stress ({stress}); }}
fluid
{{
    type faultPressure;
    fracture fault;
    initial 10e6;
    storage 2e-9;
    transmissivity 2e-10;
    {flow}
    wells {{ injector {{ position ({" ".join(num(v) for v in w)}); rate 3e-3; }} }}
}}
"""


def turn_mesh(text, R):
    """The .msh (4.1, ASCII) with every node of $Nodes moved to R x."""
    lines = text.split("\n")
    start = lines.index("$Nodes")
    blocks = int(lines[start + 1].split()[0])
    i = start + 2
    for _ in range(blocks):
        _, _, parametric, count = (int(v) for v in lines[i].split())
        if parametric:
            fail("parametric nodes in the mesh")
        i += 1 + count  # the header, then the tags
        for j in range(i, i + count):
            x = [float(v) for v in lines[j].split()]
            lines[j] = " ".join(repr(v) for v in apply(R, x))
        i += count
    if lines[i] != "$EndNodes":
        fail("the mesh's $Nodes section did not end where expected")
    return "\n".join(lines)


def read_table(path):
    lines = open(path).read().splitlines()
    header = lines[0][1:].split()
    rows = []
    for line in lines[1:]:
        if line.startswith("#") or not line.strip():
            continue
        items = line.split()
        row = {k: float(v) for k, v in zip(header[:-1], items[:-1])}
        row["state"] = items[-1]
        rows.append(row)
    if len(rows) < 10:
        fail(f"{path}: only {len(rows)} rows")
    return rows


def run_case(name, R, model, mesh_text):
    d = os.path.join(work, name)
    shutil.copytree(os.path.join(work, "template"), d)
    with open(os.path.join(d, "constant", "mesh", "box.msh"), "w") as f:
        f.write(turn_mesh(mesh_text, R) if R is not IDENTITY else mesh_text)
    with open(os.path.join(d, "constant", "effects"), "w") as f:
        f.write(effects(R, model))
    for tool in ("splitFractureNodes", "frictionSolver"):
        with open(os.path.join(d, f"log.{tool}"), "w") as log:
            rc = subprocess.call([os.path.join(bin_dir, tool), "-case", d], stdout=log,
                                 stderr=subprocess.STDOUT, timeout=300)
        if rc != 0:
            fail(f"{name}: {tool} exited {rc}: " + open(os.path.join(d, f"log.{tool}")).read()[-600:])
    steps = [l for l in open(os.path.join(d, "log.frictionSolver")) if l.startswith("Time = ")]
    if len(steps) != 2 or not all(" converged" in l for l in steps):
        fail(f"{name}: expected 2 converged steps: {steps}")
    return {t: read_table(os.path.join(d, t, "fractures", "fault.dat")) for t in ("86400", "345600")}


def strike_dip(n):
    """The README's rule for a dipping fault: dip down the plane, strike horizontal with the
    fault dipping to its right."""
    down = [n[2] * n[0], n[2] * n[1], -1 + n[2] * n[2]]
    m = math.sqrt(dot(down, down))
    dip = [v / m for v in down]
    h = math.hypot(dip[0], dip[1])
    return [-dip[1] / h, dip[0] / h, 0.0], dip


def check_columns(name, rows):
    """slipStrike/slipDip and tauStrike/tauDip: the tangential vectors on the README's basis."""
    scale_s = max(r["slipMagnitude"] for r in rows)
    scale_t = max((r["tauMagnitude"] for r in rows if r["state"] != "tip"), default=0)
    checked = 0
    for r in rows:
        n = [r["nx"], r["ny"], r["nz"]]
        # The jump is Omega+ minus Omega-, n_Gamma from Omega+ to Omega-: Omega+ is the
        # hanging wall (above the fault) when n_Gamma points down. The columns give the
        # hanging wall's slip.
        side = 1 if n[2] < 0 else -1
        slip = [side * r["slipX"], side * r["slipY"], side * r["slipZ"]]
        if abs(dot(n, slip)) > 1e-12 * scale_s:
            fail(f"{name}: the slip vector is not tangential at {r}")
        if abs(math.hypot(r["slipStrike"], r["slipDip"]) - r["slipMagnitude"]) > 1e-12 * scale_s:
            fail(f"{name}: slipStrike^2 + slipDip^2 != slipMagnitude^2 at {r}")
        if r["state"] != "tip" and abs(math.hypot(r["tauStrike"], r["tauDip"]) -
                                       r["tauMagnitude"]) > 1e-12 * scale_t:
            fail(f"{name}: tauStrike^2 + tauDip^2 != tauMagnitude^2 at {r}")
        mag = r["slipMagnitude"]
        if mag < 1e-3 * scale_s:
            continue
        # The strike and dip vectors the columns imply: slip = a s + b d with s, d orthonormal in
        # the plane, d = +-(n x s): s = (a slip + b (slip x n) sign) / |slip|^2 for one sign;
        # they must be the README's (and s horizontal, d down the plane).
        a, b = r["slipStrike"], r["slipDip"]
        sxn = [slip[1] * n[2] - slip[2] * n[1], slip[2] * n[0] - slip[0] * n[2],
               slip[0] * n[1] - slip[1] * n[0]]
        s_rule, d_rule = strike_dip(n)
        found = False
        for sign in (1, -1):
            s = [(a * slip[i] + sign * b * sxn[i]) / mag**2 for i in range(3)]
            d = [(b * slip[i] - sign * a * sxn[i]) / mag**2 for i in range(3)]
            if (abs(s[2]) < 1e-9 and d[2] < 0 and abs(dot(s, d)) < 1e-9 and
                    max(abs(x - y) for x, y in zip(s, s_rule)) < 1e-9 and
                    max(abs(x - y) for x, y in zip(d, d_rule)) < 1e-9):
                found = True
        if not found:
            fail(f"{name}: slipStrike, slipDip do not come from a horizontal strike and the "
                 f"down-dip vector of the README's rule at {r}")
        checked += 1
    if checked < 5:
        fail(f"{name}: only {checked} slipping rows to check the strike and dip on")
    return checked


def compare(name, R, base, turned, same_strike_dip):
    worst = {}
    for t in base:
        b_rows, t_rows = base[t], turned[t]
        if len(b_rows) != len(t_rows):
            fail(f"{name} at {t}: {len(t_rows)} rows, {len(b_rows)} unturned")
        RT = transpose(R)
        # Corresponding nodes: R^T x' = x (to 1e-6 m in a 2 km box).
        index = {}
        for r in b_rows:
            index[tuple(round(v, 3) for v in (r["x"], r["y"], r["z"]))] = r
        keys = {
            "slipMagnitude": lambda r: r["slipMagnitude"],
            "tauMagnitude": lambda r: r["tauMagnitude"],
            "sigmaN": lambda r: r["sigmaN"],
            "pressure": lambda r: r["pressure"],
            "sigmaNEffective": lambda r: r["sigmaNEffective"],
            "ST": lambda r: r["ST"],
            "deltaCFS": lambda r: r["deltaCFS"],
        }
        if same_strike_dip:
            for k in ("slipStrike", "slipDip", "tauStrike", "tauDip"):
                keys[k] = lambda r, k=k: r[k]
        inner = [r for r in b_rows if r["state"] != "tip"]
        scale = {k: max(abs(f(r)) for r in inner) for k, f in keys.items()}
        scale["slip"] = scale["slipMagnitude"]
        if scale["slipMagnitude"] <= 0:
            fail(f"{name} at {t}: no slip in the unturned run: nothing to compare")
        matched = 0
        for r in t_rows:
            x = apply(RT, [r["x"], r["y"], r["z"]])
            b = index.get(tuple(round(v, 3) for v in x))
            if b is None or max(abs(u - v) for u, v in zip(x, (b["x"], b["y"], b["z"]))) > 1e-6:
                fail(f"{name} at {t}: no unturned node at R^T x = {x}")
            matched += 1
            if r["state"] != b["state"]:
                fail(f"{name} at {t}: state {r['state']}, unturned {b['state']} at {x}")
            if r["state"] == "tip":
                continue
            for k, f in keys.items():
                err = abs(f(r) - f(b)) / scale[k]
                worst[k] = max(worst.get(k, 0), err)
                if err > TOL:
                    fail(f"{name} at {t}: {k} {f(r)!r} against {f(b)!r} unturned at {x} "
                         f"({err:.3g} of the largest, above {TOL:g})")
            # The slip vector turns with the body; its sign is the side n_Gamma points to.
            n_b = apply(R, [b["nx"], b["ny"], b["nz"]])
            side = 1 if dot(n_b, [r["nx"], r["ny"], r["nz"]]) > 0 else -1
            expected = [side * v for v in apply(R, [b["slipX"], b["slipY"], b["slipZ"]])]
            err = max(abs(u - v) for u, v in zip(expected, (r["slipX"], r["slipY"], r["slipZ"])))
            err /= scale["slip"]
            worst["slip vector"] = max(worst.get("slip vector", 0), err)
            if err > TOL:
                fail(f"{name} at {t}: the slip vector is not R times the unturned one at {x}")
        if matched != len(b_rows):
            fail(f"{name} at {t}: {matched} of {len(b_rows)} rows matched")
    return worst


def main():
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    template = os.path.join(work, "template")
    shutil.copytree(os.path.join(src, "tests", "regression", "cases", "wellInBox"), template)
    mesh_dir = os.path.join(template, "constant", "mesh")
    with open(os.path.join(work, "log.gmsh"), "w") as log:
        rc = subprocess.call(["gmsh", "-3", "-format", "msh41", "box.geo", "-o", "box.msh"],
                             cwd=mesh_dir, stdout=log, stderr=subprocess.STDOUT)
    if rc != 0 or "Error" in open(os.path.join(work, "log.gmsh")).read():
        fail("gmsh failed: see " + os.path.join(work, "log.gmsh"))
    mesh_text = open(os.path.join(mesh_dir, "box.msh")).read()
    os.remove(os.path.join(mesh_dir, "box.msh"))

    for model in ("closedForm", "diffusion"):
        runs = {turn: run_case(f"{model}-{turn}", R, model, mesh_text) for turn, R in TURNS.items()}
        base = runs["base"]
        last = base["345600"]
        slipping = sum(r["state"] == "slip" for r in last)
        if slipping < 5:
            fail(f"{model}: only {slipping} slipping nodes in the unturned run at four days")
        for turn, tables in runs.items():
            for t, rows in tables.items():
                check_columns(f"{model}-{turn} at {t}", rows)
                # sigma_zz the largest compression (normal faulting) while the vertical stays:
                # the hanging wall slips down dip, and the traction on it points up dip.
                if turn in ("base", "aboutZ"):
                    wrong = [r for r in rows if r["state"] == "slip" and
                             not (r["slipDip"] > 0 and r["tauDip"] < 0)]
                    if wrong:
                        fail(f"{model}-{turn} at {t}: {len(wrong)} slipping nodes with slipDip <= 0 "
                             f"or tauDip >= 0 (not a normal fault's slip): {wrong[0]}")
        for turn in ("aboutZ", "generic"):
            worst = compare(f"{model}-{turn}", TURNS[turn], base, runs[turn], turn == "aboutZ")
            print(f"PASS: {model}, turned {turn}: {slipping} slipping nodes of {len(last)}; largest "
                  "relative differences " + ", ".join(f"{k} {v:.2g}" for k, v in worst.items()))
    print("PASS: pressure invariance under rotation (closed form and diffusion)")


main()
