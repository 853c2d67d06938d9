#!/usr/bin/python3
"""getfemComparison: libfriction against an independent GetFEM 5.4 solver, paper benchmark.

For each mesh n (default 80 and 160) and order (P1, P2) it runs, on the same FreeFEM mesh
(cases/paperBenchmark remeshed with its Allmesh -n N), splitFractureNodes + frictionSolver
(semismoothNewton, tolerance 1e-12) and getfemPaperBenchmark.py (GetFEM's Newton to
round-off), measures both slips against a fine reference (libfriction P2 at n = --ref,
tolerance 1e-12) and prints a markdown table with the wall times and their ratio.

Usage: getfemComparison.py [--bin DIR] [--work DIR] [--meshes 80 160] [--orders 1 2]
                           [--ref 320] [--repeat 1] [--timeout S]
Needs python3-getfem (Debian package, optional for the project); without it, it says so
and exits 0 having done nothing. Writes <work>/getfemComparison.md.
"""
import argparse
import os
import re
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.realpath(__file__))
sys.path.insert(0, HERE)
import frictionStudy as fs  # noqa: E402

STEP_SECONDS = re.compile(r"\[step \d+/\d+, (\S+) s")
GF_TIMES = re.compile(r"read (\S+) s\s+setup (\S+) s\s+solve (\S+) s\s+total (\S+) s")
GF_ITERS = re.compile(r"dofs (\d+), fracture nodes (\d+), Newton iterations (\d+), converged (\w+)")


def run_getfem(case, order, out, timeout):
    cmd = [sys.executable, os.path.join(HERE, "getfemPaperBenchmark.py"), "-case", case,
           "--order", str(order), "--out", out]
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       timeout=timeout)
    t, it = GF_TIMES.search(r.stdout), GF_ITERS.search(r.stdout)
    if r.returncode != 0 or not t or not it:
        raise RuntimeError("getfemPaperBenchmark failed (exit %d):\n%s" % (r.returncode, r.stdout))
    tab = np.loadtxt(out)
    return dict(read=float(t.group(1)), setup=float(t.group(2)), solve=float(t.group(3)),
                total=float(t.group(4)), dofs=int(it.group(1)), iterations=int(it.group(3))), \
        {"x": tab[:, 0], "s": tab[:, 0], "slip": tab[:, 1]}


def run_libfriction(work, base, tag, order, binary, timeout):
    res, tab = fs.run_one(work, base, tag, order, "semismoothNewton", 1e-12, 200, None, binary,
                          timeout)
    if tab is None or res["status"] != "converged":
        raise RuntimeError("frictionSolver %s: %s" % (tag, res["status"]))
    with open(os.path.join(work, "runs", tag, "log.frictionSolver")) as f:
        text = f.read()
    # the solve: the factorisation (the interface operator comes out of it) and the step
    m, f = STEP_SECONDS.search(text), re.search(r"^Factorisations \d+ \((\S+) s\)", text, re.M)
    res["stepSeconds"] = float(m.group(1)) + float(f.group(1)) if m and f else float("nan")
    d = re.search(r"(\d+) dofs", text)
    res["dofs"] = int(d.group(1)) if d else 0
    return res, tab


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[1],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--bin", default=os.path.join(fs.REPO, "build", "bin"))
    p.add_argument("--work", default=os.path.join(fs.REPO, "build", "getfemComparison"))
    p.add_argument("--meshes", type=int, nargs="+", default=[80, 160])
    p.add_argument("--orders", type=int, nargs="+", default=[1, 2], choices=(1, 2))
    p.add_argument("--ref", type=int, default=320, help="n of the P2 reference (libfriction)")
    p.add_argument("--repeat", type=int, default=1, help="timings: the best of N runs")
    p.add_argument("--sweep", type=int, nargs="*", default=[60, 100, 120, 140, 200, 240],
                   help="extra meshes for libfriction alone: its cheapest run at GetFEM's "
                   "accuracy")
    p.add_argument("--timeout", type=float, default=1800)
    a = p.parse_args()
    try:
        import getfem  # noqa: F401
    except ImportError:
        print("getfemComparison: python3-getfem is not installed (optional; Debian: "
              "apt-get install python3-getfem): comparison skipped")
        return
    work = os.path.abspath(a.work)
    os.makedirs(work, exist_ok=True)
    for exe in ("splitFractureNodes", "frictionSolver"):
        if not os.access(os.path.join(a.bin, exe), os.X_OK):
            sys.exit("getfemComparison: %s not found in %s (use --bin)" % (exe, a.bin))

    t0 = time.perf_counter()
    refbase = fs.base_case(work, "paperBenchmark", "n=%d" % a.ref, a.ref)
    refres, ref = run_libfriction(work, refbase, "reference_P2_n%d" % a.ref, 2, a.bin,
                                  a.timeout)
    print("reference: libfriction P2 n=%d (%d dofs), %.1f s" % (a.ref, refres["dofs"],
                                                                  refres["wallSeconds"]))
    rows = []
    for n in a.meshes:
        base = fs.base_case(work, "paperBenchmark", "n=%d" % n, n)
        for k in a.orders:
            lf, gf_ = None, None
            for i in range(a.repeat):
                r, ltab = run_libfriction(work, base, "libfriction_P%d_n%d" % (k, n), k, a.bin,
                                          a.timeout)
                if lf is None or r["wallSeconds"] < lf["wallSeconds"]:
                    lf = r
                g, gtab = run_getfem(base, k, os.path.join(work, "getfem_P%d_n%d.dat" % (k, n)),
                                     a.timeout)
                if gf_ is None or g["total"] < gf_["total"]:
                    gf_ = g
            if ltab["x"].size != gtab["x"].size:
                raise RuntimeError("n=%d P%d: %d libfriction and %d GetFEM fracture nodes"
                                   % (n, k, ltab["x"].size, gtab["x"].size))
            o = np.argsort(ltab["x"])
            row = dict(n=n, k=k, lf=lf, gf=gf_,
                       diff=np.abs(ltab["slip"][o] - gtab["slip"]).max(),
                       slipmax=np.abs(ltab["slip"]).max(),
                       elf=fs.pb_error(ltab, ref), egf=fs.pb_error(gtab, ref))
            rows.append(row)
            print("n=%d P%d: libfriction %.3f s (solve %.3f s), error %.2e; GetFEM %.3f s "
                  "(solve %.3f s, %d Newton iterations), error %.2e; max slip difference "
                  "%.2e; ratio %.1f" % (n, k, lf["wallSeconds"], lf["stepSeconds"], row["elf"],
                                        gf_["total"], gf_["solve"], gf_["iterations"],
                                        row["egf"], row["diff"],
                                        gf_["total"] / lf["wallSeconds"]), flush=True)

    # Equal accuracy, measured: libfriction's cheapest run (same order, any mesh of the
    # comparison or of the sweep) whose slip error is at most GetFEM's.
    curve = {(r["k"], r["n"]): (r["lf"]["wallSeconds"], r["elf"]) for r in rows}
    for n in sorted(set(a.sweep) - set(a.meshes)):
        base = fs.base_case(work, "paperBenchmark", "n=%d" % n, n)
        for k in a.orders:
            best = None
            for i in range(a.repeat):
                r, ltab = run_libfriction(work, base, "libfriction_P%d_n%d" % (k, n), k, a.bin,
                                          a.timeout)
                best = r["wallSeconds"] if best is None else min(best, r["wallSeconds"])
            curve[(k, n)] = (best, fs.pb_error(ltab, ref))
            print("sweep n=%d P%d: libfriction %.3f s, error %.2e" % (n, k, *curve[(k, n)]),
                  flush=True)
    for r in rows:
        ok = [(t, n, e) for (k, n), (t, e) in curve.items() if k == r["k"] and e <= r["egf"]]
        r["eq"] = min(ok) if ok else None

    nproc, cpu, mem = fs.machine()
    md = ["| mesh | order | dofs (libfriction / GetFEM) | GetFEM wall [s] (solve) | Newton its "
          "(GetFEM / libfriction) | libfriction wall [s] (solve) | ratio whole (solve) | "
          "slip error libfriction | slip error GetFEM | max slip difference | libfriction at "
          "GetFEM's accuracy: mesh, wall, ratio |",
          "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lf, g = r["lf"], r["gf"]
        eq = ("n = %d, %.3f s, **%.1f×**" % (r["eq"][1], r["eq"][0], g["total"] / r["eq"][0])
              if r["eq"] else "not reached in the sweep")
        md.append("| n = %d | P%d | %d / %d | %.2f (%.2f) | %d / %d | %.3f (%.3f) "
                  "| %.1f× (%.1f×) | %.2e | %.2e | %.1e | %s |" % (
                      r["n"], r["k"], lf["dofs"], g["dofs"], g["total"], g["solve"],
                      g["iterations"], lf["iterations"], lf["wallSeconds"], lf["stepSeconds"],
                      g["total"] / lf["wallSeconds"], g["solve"] / lf["stepSeconds"], r["elf"],
                      r["egf"], r["diff"], eq))
    md += ["", "Reference: libfriction P2, n = %d, semismoothNewton at 1e-12 (%d dofs, %.1f s). "
           "Slip error: relative L²(Γ) against it. GetFEM wall: read + setup + solve inside "
           "getfemPaperBenchmark.py (no interpreter start-up), solve = Model.solve (assembly, "
           "a factorisation per Newton iteration); libfriction wall: the whole frictionSolver "
           "process (reading, assembly, factorisation, Newton, writing), solve = its "
           "factorisation plus its step time (Newton). Last column: libfriction's cheapest "
           "measured run of the same order (meshes %s) whose slip error is at most GetFEM's, "
           "and GetFEM's wall over its wall. Best of %d. Machine: %s cores, %s, %s; "
           "total %.0f s."
           % (a.ref, refres["dofs"], refres["wallSeconds"],
              ", ".join(str(n) for n in sorted(set(a.sweep) | set(a.meshes))), a.repeat,
              nproc, cpu, mem, time.perf_counter() - t0)]
    text = "\n".join(md) + "\n"
    with open(os.path.join(work, "getfemComparison.md"), "w") as f:
        f.write(text)
    print()
    print(text)


if __name__ == "__main__":
    main()
