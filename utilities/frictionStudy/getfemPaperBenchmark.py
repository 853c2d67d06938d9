#!/usr/bin/python3
"""getfemPaperBenchmark: the paper benchmark solved independently with GetFEM 5.4.

Reads a cases/paperBenchmark case folder (the FreeFEM mesh and labels named in
system/meshDict, regions 1 below and 2 above the fracture, and the values in
constant/mechanicalProperties, constant/fractureProperties and 0/D), solves
the frictional problem on the same triangles with GetFEM's assembly and Newton, and
writes the slip at the fracture nodes with the wall times of each phase.

Usage: getfemPaperBenchmark.py -case DIR [--order 1|2] [--model bilateral|brick]
           [--out FILE] [--maxRes R] [--r R] [--maxIter N] [--noisy]

How the GetFEM model is set up (GetFEM 5.4.2, Debian python3-getfem):
* The mesh is cut along the fracture by building two GetFEM meshes from the same file:
  the triangles of region 1 (below y = 0.5) and those of region 2 (above), so the fracture
  nodes are duplicated as in constant/splitMesh. Each block has its own displacement, a
  Lagrange P_k fem (FEM_PK(2,k), k = --order) on straight triangles (GT_PK(2,1)),
  integrated with IM_TRIANGLE(2k).
* Elasticity: add_isotropic_linearized_elasticity_brick on each block (GetFEM's 2D
  isotropic brick is plane strain), λ and μ from constant/mechanicalProperties.
* Fracture, --model bilateral (the default; the paper's model): a Lagrange multiplier
  `traction` (P_k, both components, on the lower block's fracture edges: the force per
  length on the lower face) written in GetFEM's weak form language. The upper block is
  reached from the lower block's fracture edges through
  add_interpolate_transformation_from_expression (identity map X, lower mesh -> upper
  mesh); jump = u_upper - u_lower. Terms on Γ: traction·(v_upper - v_lower) (linear),
  the bilateral normal condition (jump·n) μ·n = 0 (linear, n = (0, 1)), and Coulomb's law
  in the Alart-Curnier form (1/r)(λ_t - P_B(λ_t + r jump_t, f (-λ·n)⁺))·μ = 0 with GWFL's
  Ball_projection and pos_part (nonlinear term), f from constant/fractureProperties.
  Dirichlet values are eliminated exactly: the lower block's space leaves out the bottom
  dofs (u = 0); the upper block's displacement is utop + w with w = 0 on the top (a
  constant translation has no strain), utop the final value of the top table in 0/D.
* Fracture, --model brick (a cross-check with GetFEM's own contact brick):
  add_integral_contact_between_nonmatching_meshes_brick, option 1 (non-symmetric
  Alart-Curnier augmented Lagrangian, integral form), same multiplier space, Dirichlet by
  add_Dirichlet_condition_with_simplification. This brick is unilateral (contact with
  possible opening); it is the paper's bilateral model only when the whole fracture is in
  compression, which the script checks (max σ_n < 0 at the fracture nodes, else exit 3).
  Its Dirichlet post-treatment is re-applied at every Newton iteration and grows faster
  than the system (about 1.2 s per iteration at P2, n = 80), which is why the default
  model eliminates the Dirichlet dofs instead.
* r (the augmentation, Pa/m): default E (GetFEM's documentation advises a value close to
  the Young modulus; here it gives the fewest Newton iterations). The discrete solution
  depends on r slightly (the projection acts at quadrature points): 2·10⁻⁷ in the slip
  between r = E and 10 E at n = 80, 10⁻⁴ of the slip.
* Newton: Model.solve (GetFEM's Newton with its default line search and linear solver,
  MUMPS here; 'superlu' segfaults in Debian's 5.4.2), stopped when GetFEM's residual,
  relative to the first one, is below --maxRes (default 1e-10: it stagnates at ~3·10⁻¹²,
  round-off, one iteration after crossing 1e-10) or at --maxIter (100). GetFEM assembles
  and factorises the tangent matrix at every iteration.
Output (--out, default <case>/getfem/fracture_P<k>.dat): columns x slip sigma_n tau at
the fracture nodes (vertices and, for P2, edge midpoints), sorted by x, with libfriction's
conventions: slip = (u_upper - u_lower)·(1, 0), σ_n < 0 in compression, τ the tangential
traction on the upper face. Printed: read, setup and solve wall times, Newton iterations,
dofs, max σ_n, slip at x = 0.5. Exit 0 converged, 1 bad input, 3 not converged (or, brick
model, σ_n ≥ 0 somewhere).
"""
import argparse
import os
import re
import sys
import time

import numpy as np


def fail(msg, code=1):
    print("getfemPaperBenchmark: " + msg, file=sys.stderr)
    sys.exit(code)


def read_text(path):
    """A dictionary's text without // comments."""
    try:
        with open(path) as f:
            return re.sub(r"//.*", "", f.read())
    except OSError as e:
        fail("cannot read %s: %s" % (path, e.strerror))


def read_value(path, key):
    """The number after `key` in an OpenFOAM-style dictionary (first occurrence)."""
    text = read_text(path)
    m = re.search(r"(?m)^\s*%s\s+([-+0-9.eE]+)\s*;" % re.escape(key), text)
    if not m:
        fail("%s: no numeric entry '%s'" % (path, key))
    return float(m.group(1))


def read_case(case):
    mech = os.path.join(case, "constant", "mechanicalProperties")
    if re.search(r"(?m)^\s*planeStress\s+(yes|true|on)\s*;", read_text(mech)):
        fail("%s: planeStress yes is not supported (the benchmark is plane strain)" % mech)
    lam, mu = read_value(mech, "lambda"), read_value(mech, "mu")
    fric = read_value(os.path.join(case, "constant", "fractureProperties"),
                      "frictionCoefficient")
    dpath = os.path.join(case, "0", "D")
    text = read_text(dpath)
    m = re.search(r"top\s*\{[^}]*\}", text)
    pairs = re.findall(r"\(\s*([-+0-9.eE]+)\s*\(\s*([-+0-9.eE]+)\s+([-+0-9.eE]+)\s*\)\s*\)",
                       m.group(0)) if m else []
    if not pairs:
        fail("%s: top: expected 'value table ((t (ux uy)) ...)'" % dpath)
    t, ux, uy = (float(v) for v in max(pairs, key=lambda p: float(p[0])))
    # the mesh and its labels as system/meshDict names them for libfriction
    mdict = os.path.join(case, "system", "meshDict")
    text = read_text(mdict)
    m = re.search(r'(?m)^\s*mesh\s+"([^"]+)"\s*;', text)
    if not m:
        fail('%s: no entry mesh "FILE";' % mdict)
    labels = {}
    for patch in ("bottom", "top", "fracture"):
        lab = re.search(r"(?m)^\s*%s\s+(\d+)\s*;" % patch, text)
        if not lab:
            fail("%s: patches: no numeric label for '%s'" % (mdict, patch))
        labels[patch] = int(lab.group(1))
    return dict(lam=lam, mu=mu, fric=fric, top=(ux, uy), mesh=os.path.join(case, m.group(1)),
                labels=labels)


def read_freefem_mesh(path):
    """FreeFEM .msh: 'nv nt nbe', nv lines 'x y label', nt lines 'i j k region', nbe lines
    'i j label' (1-based)."""
    try:
        with open(path) as f:
            tok = f.read().split()
    except OSError as e:
        fail("cannot read %s: %s" % (path, e.strerror))
    try:
        nv, nt, nbe = int(tok[0]), int(tok[1]), int(tok[2])
        a = np.array(tok[3:3 + 3 * nv + 4 * nt + 3 * nbe], dtype=float)
        if a.size != 3 * nv + 4 * nt + 3 * nbe:
            raise ValueError
    except (ValueError, IndexError):
        fail("%s: not a FreeFEM mesh (header 'nv nt nbe' and that many lines)" % path)
    pts = a[:3 * nv].reshape(nv, 3)[:, :2]
    tri = a[3 * nv:3 * nv + 4 * nt].reshape(nt, 4).astype(int)
    edges = a[3 * nv + 4 * nt:].reshape(nbe, 3).astype(int)
    return pts, tri[:, :3] - 1, tri[:, 3], edges[:, :2] - 1, edges[:, 2]


def build_block(gf, pts, tri, edges, elabel, labels):
    """A GetFEM mesh of the triangles `tri` and one boundary region per label in `labels`
    (region number = label) made of the edges with that label that bound these triangles."""
    m = gf.Mesh("empty", 2)
    gt = gf.GeoTrans("GT_PK(2,1)")
    P = np.transpose(pts[tri], (2, 1, 0))        # 2 x 3 x nt: the points of each triangle
    cvids = np.asarray(m.add_convex(gt, P), dtype=int).ravel()
    where = {}
    for t, (a, b, c) in enumerate(tri):
        # face f of a GT_PK(2,1) simplex is the one opposite its vertex f
        for f, e in ((0, (b, c)), (1, (a, c)), (2, (a, b))):
            where[(min(e), max(e))] = (cvids[t], f)
    for lab in labels:
        faces = [where[(min(e), max(e))] for e, l in zip(edges, elabel)
                 if l == lab and (min(e), max(e)) in where]
        if not faces:
            fail("no edge labelled %d bounds this block" % lab)
        m.set_region(lab, np.array(faces, dtype=int).T)
    return m


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("-case", "--case", required=True)
    p.add_argument("--order", type=int, default=1, choices=(1, 2))
    p.add_argument("--out")
    p.add_argument("--maxRes", type=float, default=1e-10)
    p.add_argument("--r", type=float, help="augmentation parameter r [Pa/m] (default E)")
    p.add_argument("--lsolver", default="auto")
    p.add_argument("--model", default="bilateral", choices=("bilateral", "brick"))
    p.add_argument("--maxIter", type=int, default=100)
    p.add_argument("--noisy", action="store_true")
    a = p.parse_args()
    try:
        import getfem as gf
    except ImportError:
        fail("python3-getfem is not installed (Debian: apt-get install python3-getfem)")
    gf.util_trace_level(0)
    gf.util_warning_level(0)
    case = a.case

    t0 = time.perf_counter()
    par = read_case(case)
    BOTTOM, TOP, FRAC = (par["labels"][p] for p in ("bottom", "top", "fracture"))
    pts, tri, region, edges, elabel = read_freefem_mesh(par["mesh"])
    t_read = time.perf_counter() - t0

    t0 = time.perf_counter()
    k = a.order
    n = int(np.sum(elabel == FRAC))               # fracture edges: h = 1/n
    lower = build_block(gf, pts, tri[region == 1], edges, elabel, (BOTTOM, FRAC))
    upper = build_block(gf, pts, tri[region == 2], edges, elabel, (TOP, FRAC))
    fem = gf.Fem("FEM_PK(2,%d)" % k)
    # order 2k: exact for the P_k x P_k mass matrices on the fracture edges (a lower order
    # makes the multiplier coupling singular: checkerboard modes)
    im = gf.Integ("IM_TRIANGLE(%d)" % (2 * k))
    mf1, mf2 = gf.MeshFem(lower, 2), gf.MeshFem(upper, 2)
    mf1.set_fem(fem)
    mf2.set_fem(fem)
    mim1, mim2 = gf.MeshIm(lower, im), gf.MeshIm(upper, im)
    lenfrac = gf.asm_generic(mim1, 0, "1", FRAC)
    if abs(lenfrac - 1.0) > 1e-12:
        fail("the fracture edges of the lower block have length %.15g, expected 1" % lenfrac)

    young = par["mu"] * (3 * par["lam"] + 2 * par["mu"]) / (par["lam"] + par["mu"])
    md = gf.Model("real")
    md.add_initialized_data("lambda", [par["lam"]])
    md.add_initialized_data("mu", [par["mu"]])
    md.add_initialized_data("r", [a.r if a.r else young])
    md.add_initialized_data("friction", [par["fric"]])
    md.add_initialized_data("utop", list(par["top"]))
    if a.model == "bilateral":
        # Exact elimination of the Dirichlet dofs: u1 = 0 on the bottom, and the upper
        # block's displacement is utop + w2 with w2 = 0 on the top (a translation has no
        # strain, so the elasticity of w2 is that of u2); both spaces are restrictions
        # of the P_k space ('partial' mesh_fem), so nothing is penalised or modified.
        keep1 = np.setdiff1d(np.arange(mf1.nbdof()), mf1.basic_dof_on_region(BOTTOM))
        keep2 = np.setdiff1d(np.arange(mf2.nbdof()), mf2.basic_dof_on_region(TOP))
        mv1, mv2 = gf.MeshFem("partial", mf1, keep1), gf.MeshFem("partial", mf2, keep2)
        md.add_fem_variable("u1", mv1)
        md.add_fem_variable("w2", mv2)
        md.add_isotropic_linearized_elasticity_brick(mim1, "u1", "lambda", "mu")
        md.add_isotropic_linearized_elasticity_brick(mim2, "w2", "lambda", "mu")
        md.add_filtered_fem_variable("traction", mf1, FRAC)
        # the upper block seen from the lower block's fracture edges (matching points)
        md.add_interpolate_transformation_from_expression("up", lower, upper, "X")
        md.add_macro("jump", "Interpolate(w2,up) + utop - u1")
        md.add_macro("nrm", "[0;1]")          # outward normal of the lower block on Γ
        md.add_macro("tang(v)", "(v - (v.nrm)*nrm)")
        # traction = force per length on the lower face; the upper face gets -traction
        md.add_linear_term(mim1, "traction.(Interpolate(Test_w2,up) - Test_u1)", FRAC)
        md.add_linear_term(mim1, "(jump.nrm)*(Test_traction.nrm)", FRAC)
        md.add_nonlinear_term(
            mim1, "(1/r)*(tang(traction) - Ball_projection(tang(traction + r*jump), "
            "friction*pos_part(-traction.nrm))).Test_traction", FRAC)
        vname2, mfv2 = "w2", mv2
    else:
        md.add_fem_variable("u1", mf1)
        md.add_fem_variable("u2", mf2)
        md.add_isotropic_linearized_elasticity_brick(mim1, "u1", "lambda", "mu")
        md.add_isotropic_linearized_elasticity_brick(mim2, "u2", "lambda", "mu")
        md.add_initialized_data("zero", [0.0, 0.0])
        md.add_Dirichlet_condition_with_simplification("u1", BOTTOM, "zero")
        md.add_Dirichlet_condition_with_simplification("u2", TOP, "utop")
        md.add_filtered_fem_variable("traction", mf1, FRAC)
        md.add_integral_contact_between_nonmatching_meshes_brick(
            mim1, "u1", "u2", "traction", "r", "friction", FRAC, FRAC, 1)
        vname2, mfv2 = "u2", mf2
    ndof = md.nbdof()
    t_setup = time.perf_counter() - t0

    t0 = time.perf_counter()
    nit, conv = md.solve("max_res", a.maxRes, "max_iter", a.maxIter, "lsolver", a.lsolver,
                         *(["noisy"] if a.noisy else []))
    t_solve = time.perf_counter() - t0
    res = np.linalg.norm(md.rhs())          # the last assembled residual

    # fracture nodes: the dof nodes of mf1 on the fracture (vertices and, P2, midpoints)
    dofs = mf1.basic_dof_on_region(FRAC)
    nodes = mf1.basic_dof_nodes(dofs)
    xy = np.unique(np.round(nodes.T, 14), axis=0)
    xy = xy[np.argsort(xy[:, 0])].T
    u1 = gf.compute_interpolate_on(md.mesh_fem_of_variable("u1"), md.variable("u1"), xy)
    u2 = gf.compute_interpolate_on(mfv2, md.variable(vname2), xy)
    if a.model == "bilateral":
        u2 = u2 + np.asarray(par["top"]).reshape(2, 1)
    tr = gf.compute_interpolate_on(md.mesh_fem_of_variable("traction"),
                                   md.variable("traction"), xy)
    slip = u2[0] - u1[0]
    sigma_n, tau = tr[1], -tr[0]       # tr: traction on the lower face, normal (0, 1)

    out = a.out or os.path.join(case, "getfem", "fracture_P%d.dat" % k)
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    tmp = out + ".tmp"
    with open(tmp, "w") as f:
        f.write("# x slip sigma_n tau   (GetFEM, P%d, n = %d)\n" % (k, n))
        for row in zip(xy[0], slip, sigma_n, tau):
            f.write("%.15g %.15g %.15g %.15g\n" % row)
    os.replace(tmp, out)
    print("GetFEM P%d n=%d: dofs %d, fracture nodes %d, Newton iterations %d, converged %s, "
          "residual %.3g" % (k, n, ndof, xy.shape[1], nit, bool(conv), res))
    print("read %.3f s  setup %.3f s  solve %.3f s  total %.3f s"
          % (t_read, t_setup, t_solve, t_read + t_setup + t_solve))
    print("max sigma_n %.4g (compression everywhere: %s); slip at centre %.6e; wrote %s"
          % (sigma_n.max(), sigma_n.max() < 0, np.interp(0.5, xy[0], slip), out))
    if not conv:
        sys.exit(3)
    if a.model == "brick" and sigma_n.max() >= 0:
        print("getfemPaperBenchmark: sigma_n >= 0 somewhere: the unilateral brick is not the "
              "paper's bilateral model here", file=sys.stderr)
        sys.exit(3)


if __name__ == "__main__":
    main()
