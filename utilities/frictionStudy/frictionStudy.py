#!/usr/bin/python3
"""frictionStudy: what accuracy costs in time.

Sweeps stopping tolerance, optimizer, element order and mesh on copies of
cases/inclinedCrack (2D, analytic slip), cases/paperBenchmark (2D; reference: the finest
mesh of the sweep, same order, semismoothNewton at tolerance 1e-12), cases/pennyCrack
(3D, analytic slip, measured by the case's pennyError.py) and cases/sneddonCrack (2D, a
crack opened by fluid pressure, contact unilateral: Sneddon's opening, measured by the
case's sneddonError.py; the krylov variant does not take openings), runs splitFractureNodes and
frictionSolver on each, and writes study.csv, study.md and study.png to --out. It also
measures, on the finest paperBenchmark level, how much faster semismoothNewton reaches the
slip error of 2000 steepestDescent iterations (alpha 2e-4, the paper's step; where it
diverges on that mesh, alphaRelative 1, the scale-free default).

Usage: frictionStudy.py [--quick] [--cases CASE...] [--bin DIR] [--work DIR] [--out DIR]
                        [--timeout S]
  defaults: every case, --bin <repo>/build/bin, --work <repo>/build/study,
  --out <work>/results.
Nothing is written into cases/: the case folders are copied into --work.
"""
import argparse
import csv
import math
import os
import platform
import re
import shutil
import subprocess
import sys
import threading
import time

import numpy as np

REPO = os.path.abspath(os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", ".."))

# inclinedCrack: analytic slip (cases/inclinedCrack/README.md)
A = 0.05
E_IC, NU_IC, TAU_IC, SIGN_IC, MU_IC, R_IC = 10e9, 0.25, 4.3301e6, 2.5e6, 0.4, 1.0033
CENTRE = np.array([0.5, 0.5])
DIRECTION = np.array([math.cos(math.radians(60.0)), math.sin(math.radians(60.0))])

# pennyCrack: disc radius a = 1 m (cases/pennyCrack/README.md); meshes h = a/d on the disc.
# a/16 is left out: its P2 run takes minutes and about 10 GB.
PENNY_MESHES = (4, 6, 8)
PENNY_A = 1.0

# sneddonCrack: crack half-length a = 1 m (cases/sneddonCrack/README.md); h = a/d on the crack.
SNEDDON_MESHES = (16, 32, 64)
SNEDDON_A = 1.0

CASES = ["inclinedCrack", "paperBenchmark", "pennyCrack", "sneddonCrack"]
OPTIMIZERS = ["steepestDescent", "armijo", "barzilaiBorwein", "lbfgs", "semismoothNewton",
              "semismoothNewton; variant krylov"]
CSV_COLUMNS = ["case", "mesh", "hOrN", "order", "optimizer", "tolerance", "status",
               "iterations", "backSubstitutions", "factorSeconds", "wallSeconds",
               "relResidual", "maxExcessST", "slipError"]


def sd_alpha(case, h):
    """Fixed step of steepestDescent: the solver's scale-free default (alphaRelative 1, i.e.
    (w/E)^2 with w the node spacing), stable on both 2D cases and both orders and on the
    penny's P1; on the penny's P2 it diverges within a few iterations, and the rows say so
    (status diverged). The paper's own 2e-4 is used for the promise below (P1 paper
    benchmark, where it is stable)."""
    return None


def plan(quick, cases=CASES):
    """The sweep: a list of (case, meshLabel, hOrN, order, optimizer, tolerance, maxIter)."""
    runs = []
    if quick:
        ic_meshes = [8, 16, 32]
        pb_meshes = [20, 40]
        tols = [1e-4, 1e-8]
        for d in ic_meshes:
            for order in (1, 2):
                for opt in ("lbfgs", "semismoothNewton"):
                    for tol in tols:
                        runs.append(("inclinedCrack", "a/%d" % d, A / d, order, opt, tol, 20000))
        for n in pb_meshes:
            for order in (1, 2):
                opts = ["lbfgs", "semismoothNewton"]
                if n == 20:
                    opts = ["steepestDescent", "armijo"] + opts
                for opt in opts:
                    for tol in tols:
                        mi = 2000 if opt in ("steepestDescent", "armijo") else 20000
                        runs.append(("paperBenchmark", "n=%d" % n, n, order, opt, tol, mi))
        # pennyCrack: the coarsest mesh with both orders, the next with P1 (3D runs cost
        # seconds where the 2D ones cost milliseconds; lbfgs on P2 a/4 needs 40 s for 1e-4);
        # steepestDescent checks that the default step is stable in 3D.
        for d, order in ((4, 1), (4, 2), (6, 1)):
            opts = ["semismoothNewton"] if order == 2 else ["lbfgs", "semismoothNewton"]
            if (d, order) == (4, 1):
                opts = ["steepestDescent"] + opts
            for opt in opts:
                for tol in tols:
                    mi = 2000 if opt == "steepestDescent" else 20000
                    runs.append(("pennyCrack", "a/%d" % d, PENNY_A / d, order, opt, tol, mi))
        # sneddonCrack: two meshes, both orders; L-BFGS on P1 only (on P2 a/32 it needs 45 s).
        for d in SNEDDON_MESHES[:2]:
            for order in (1, 2):
                for opt in ("lbfgs", "semismoothNewton") if order == 1 else ("semismoothNewton",):
                    for tol in tols:
                        runs.append(("sneddonCrack", "a/%d" % d, SNEDDON_A / d, order, opt, tol,
                                     20000))
    else:
        tols = [1e-2, 1e-4, 1e-6, 1e-8, 1e-10]
        for d in (8, 16, 32, 64, 128):
            for order in (1, 2):
                for opt in OPTIMIZERS:
                    for tol in tols:
                        runs.append(("inclinedCrack", "a/%d" % d, A / d, order, opt, tol, 20000))
        for n in (20, 40, 80):
            for order in (1, 2):
                for opt in OPTIMIZERS:
                    for tol in tols:
                        runs.append(("paperBenchmark", "n=%d" % n, n, order, opt, tol, 20000))
        for d in PENNY_MESHES:
            for order in (1, 2):
                for opt in OPTIMIZERS:
                    for tol in tols:
                        runs.append(("pennyCrack", "a/%d" % d, PENNY_A / d, order, opt, tol,
                                     20000))
        for d in SNEDDON_MESHES:
            for order in (1, 2):
                for opt in OPTIMIZERS:
                    if "krylov" in opt:  # refused for fractures that open
                        continue
                    for tol in tols:
                        runs.append(("sneddonCrack", "a/%d" % d, SNEDDON_A / d, order, opt, tol,
                                     20000))
    return [r for r in runs if r[0] in cases]


def sh(cmd, cwd=None, log=None):
    with open(log or os.devnull, "w") as f:
        r = subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT)
    if r.returncode != 0:
        raise RuntimeError("%s failed (exit %d) in %s%s" % (" ".join(cmd), r.returncode, cwd,
                                                          "; see " + log if log else ""))


def base_case(work, case, label, value):
    """A copy of cases/<case> with its mesh regenerated by the case's own Allmesh."""
    d = os.path.join(work, "meshes", case + "_" + label.replace("/", "").replace("=", ""))
    stamp = os.path.join(d, ".meshed")
    if os.path.exists(stamp):
        return d
    shutil.rmtree(d, ignore_errors=True)
    shutil.copytree(os.path.join(REPO, "cases", case), d,
                    ignore=shutil.ignore_patterns("log.*", "postProcessing", "VTK", "splitMesh",
                                                  "[1-9]*"))
    arg = ["-n", str(value)] if case == "paperBenchmark" else ["-h", repr(value)]
    sh(["./Allmesh"] + arg, cwd=d, log=os.path.join(d, "log.Allmesh"))
    cd = os.path.join(d, "system", "controlDict")
    with open(cd) as f:
        text = f.read()
    text = re.sub(r"(?m)^\s*writeVTK\s+[^;]*;\s*\n?", "", text)
    # pennyError.py integrates over the fault triangles, which only the .vtp gives: the
    # penny's runs write VTK (its time is in their wall time).
    with open(cd, "w") as f:
        f.write(text.rstrip("\n") + "\nwriteVTK        %s;\n"
                % ("yes" if case == "pennyCrack" else "no"))
    open(stamp, "w").close()
    return d


def set_solution(path, order, opt, tol, max_iter, alpha=None):
    with open(path) as f:
        text = f.read()
    text = re.sub(r"(?m)^(\s*elementOrder\s+)[^;]*;", r"\g<1>%d;" % order, text)
    block = ("optimizer\n    {\n        type            %s;\n        tolerance       %.3g;\n"
             "        maxIterations   %d;\n" % (opt, tol, max_iter))
    if alpha is not None:
        block += "        alpha           %.6g;\n" % alpha
    block += "    }"
    text, k = re.subn(r"optimizer\s*\{[^{}]*\}", block, text)
    if k != 1:
        raise RuntimeError("%s: no optimizer block" % path)
    with open(path, "w") as f:
        f.write(text)


def read_table(path):
    with open(path) as f:
        header = f.readline().lstrip("#").split()
        cols = {name: [] for name in header}
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            for name, v in zip(header, line.split()):
                cols[name].append(v)
    out = {}
    for name, vals in cols.items():
        try:
            out[name] = np.array([float(v) for v in vals])
        except ValueError:
            out[name] = vals
    return out


def l2(s, f):
    return math.sqrt(max(np.trapz(f * f, s), 0.0))


def ic_error(tab):
    xy = np.stack([tab["x"], tab["y"]], axis=1)
    xi = (xy - CENTRE) @ DIRECTION
    exact = R_IC * 4 * (1 - NU_IC ** 2) / E_IC * (TAU_IC - MU_IC * SIGN_IC) * \
        np.sqrt(np.clip(A * A - xi * xi, 0, None))
    return l2(tab["s"], np.abs(tab["slip"]) - exact) / l2(tab["s"], exact)


def pb_error(tab, ref):
    order = np.argsort(ref["x"])
    r = np.interp(tab["x"], ref["x"][order], ref["slip"][order])
    return l2(tab["s"], tab["slip"] - r) / l2(tab["s"], r)


STEP_RE = re.compile(r"^Time = \S+\s+iterations (\d+)\s+backSubstitutions (\d+).*?"
                     r"\|D\|/\|Sigma\| (\S+)\s+maxExcessST (\S+)\s+\|dBeta\| \S+\s+(.*?)\s+\(written\)",
                     re.M)


def run_one(work, base, tag, order, opt, tol, max_iter, alpha, binary, timeout):
    """Copies base, runs split + solve; returns a dict of measurements and the table."""
    d = os.path.join(work, "runs", tag)
    shutil.rmtree(d, ignore_errors=True)
    shutil.copytree(base, d, ignore=shutil.ignore_patterns("log.*", ".meshed"))
    set_solution(os.path.join(d, "system", "frictionSolution"), order, opt, tol, max_iter, alpha)
    sh([os.path.join(binary, "splitFractureNodes"), "-case", d],
       log=os.path.join(d, "log.splitFractureNodes"))
    log = os.path.join(d, "log.frictionSolver")
    res = {"status": "", "iterations": float("nan"), "backSubstitutions": float("nan"),
           "factorSeconds": float("nan"), "wallSeconds": float("nan"),
           "relResidual": float("nan"), "maxExcessST": float("nan")}
    # No timeout= in subprocess: its polling loop (sleeps of up to 50 ms) would quantise
    # the wall time; a blocking wait plus a timer that kills the run does not.
    killed = []
    with open(log, "w") as f:
        t0 = time.perf_counter()
        proc = subprocess.Popen([os.path.join(binary, "frictionSolver"), "-case", d], stdout=f,
                                stderr=subprocess.STDOUT)
        timer = threading.Timer(timeout, lambda: (killed.append(1), proc.kill()))
        timer.start()
        rc = proc.wait()
        res["wallSeconds"] = time.perf_counter() - t0
        timer.cancel()
    if killed:
        res["status"] = "timeout"
        return res, None
    with open(log) as f:
        text = f.read()
    m = re.search(r"Factorisation: ok \(\w+, (\S+) s\)", text)
    if m:
        res["factorSeconds"] = float(m.group(1))
    steps = STEP_RE.findall(text)
    if steps:
        it, bs, rr, ex, st = steps[-1]
        # With fractures that open the line goes on with the node states: not the status.
        st = re.sub(r"\s+nodes stick \d+ slip \d+ open \d+ tip \d+$", "", st)
        res.update(iterations=int(it), backSubstitutions=int(bs), relResidual=float(rr),
                   maxExcessST=float(ex), status=st.replace(" ", "_"))
    # The run's cost: every back-substitution, those building Newton's S once per run included.
    m = re.search(r"^Factorisations \d+ \(\S+ s\), back-substitutions (\d+)", text, re.M)
    if m:
        res["backSubstitutions"] = int(m.group(1))
    if rc not in (0, 3) or not steps:
        res["status"] = "crash(exit %d)" % rc
        return res, None
    fdir = os.path.join(d, "1", "fractures")
    tab = read_table(os.path.join(fdir, sorted(os.listdir(fdir))[0]))
    # keep the work folder small: the fields are not needed (the fault's .vtp is)
    shutil.rmtree(os.path.join(d, "1", "uniform"), ignore_errors=True)
    vtk = os.path.join(d, "VTK")
    for path in [os.path.join(d, "1", "D")] + \
            [os.path.join(vtk, f) for f in (os.listdir(vtk) if os.path.isdir(vtk) else [])
             if f.endswith(".vtu")]:
        try:
            os.remove(path)
        except OSError:
            pass
    return res, tab


_penny = []


def penny_error(run_dir):
    """relL2Error of cases/pennyCrack/pennyError.py on a run folder: the relative L2(Gamma)
    error of |slip| against the analytic penny slip (the module is imported once: each
    call as a subprocess would pay for importing VTK again)."""
    if not _penny:
        import importlib.util
        spec = importlib.util.spec_from_file_location(
            "pennyError", os.path.join(REPO, "cases", "pennyCrack", "pennyError.py"))
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        _penny.append(mod)
    mod = _penny[0]
    import contextlib
    import io
    buf = io.StringIO()
    try:
        with contextlib.redirect_stdout(buf):
            rc = mod.main(["-case", run_dir])
    except mod.InputError as e:
        raise RuntimeError("pennyError.py on %s: %s" % (run_dir, e))
    m = re.search(r"(?m)^relL2Error\s+(\S+)$", buf.getvalue())
    if rc != 0 or not m:
        raise RuntimeError("pennyError.py on %s: exit %s, no relL2Error line:\n%s"
                           % (run_dir, rc, buf.getvalue()))
    return float(m.group(1))


def sneddon_error(run_dir):
    """relL2Error of cases/sneddonCrack/sneddonError.py on a run folder: the relative L2
    error of the opening against Sneddon's."""
    script = os.path.join(REPO, "cases", "sneddonCrack", "sneddonError.py")
    r = subprocess.run([sys.executable, script, "-case", run_dir], capture_output=True, text=True)
    m = re.search(r"(?m)^relL2Error\s+(\S+)$", r.stdout)
    if r.returncode != 0 or not m:
        raise RuntimeError("sneddonError.py on %s: exit %d:\n%s%s"
                           % (run_dir, r.returncode, r.stdout, r.stderr))
    return float(m.group(1))


def machine():
    cpu = "?"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    mem = "?"
    try:
        with open("/proc/meminfo") as f:
            kb = int(f.readline().split()[1])
        mem = "%.1f GiB" % (kb / 1024 ** 2)
    except (OSError, ValueError, IndexError):
        pass
    return os.cpu_count(), cpu, mem


def fmt(v, kind="g"):
    if isinstance(v, str):
        return v
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return "—"
    if kind == "i":
        return "%d" % v
    if kind == "s":
        return "%.3g" % v
    return "%.2e" % v


def getfem_note():
    """The GetFEM comparison is its own benchmark (getfemComparison.py, a few minutes):
    this study only says where it is and whether it can run here."""
    try:
        import getfem  # noqa: F401
        return ("The comparison with an independent GetFEM 5.4 solver (same mesh, same "
                "orders, errors against a fine reference) is a separate benchmark: "
                "`/usr/bin/python3 utilities/frictionStudy/getfemComparison.py`.")
    except ImportError:
        return ("GetFEM comparison skipped: python3-getfem is not installed (optional; "
                "Debian 12 has 5.4.2: apt-get install python3-getfem, about 16 MB); with it, "
                "`utilities/frictionStudy/getfemComparison.py` runs the comparison.")


def write_outputs(out, rows, ratio_lines, mode, total_seconds, refs):
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "study.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(CSV_COLUMNS)
        for r in rows:
            w.writerow([r[c] if not isinstance(r[c], float) else "%.6g" % r[c]
                        for c in CSV_COLUMNS])
    nproc, cpu, mem = machine()
    md = ["# frictionStudy: what accuracy costs in time", "",
          "Mode: %s; total study time %.1f s." % (mode, total_seconds), "",
          "Machine: `nproc` %s, CPU %s, memory %s, Python %s." % (
              nproc, cpu, mem, platform.python_version()), "",
          "slipError: relative L²(Γ) error of the slip; " + "; ".join(
              text for case, text in (
                  ("inclinedCrack", "inclinedCrack against the analytic slip"),
                  ("paperBenchmark", "paperBenchmark against %s" % refs),
                  ("pennyCrack", "pennyCrack (3D, P1 and P2 on the same tetrahedra, h = a/d "
                   "on the disc): the error of |slip| against the analytic penny slip "
                   "(`relL2Error` of cases/pennyCrack/pennyError.py; its interpolation floor "
                   "is 0.055 (P1) and 0.015 (P2) at a/8, the cube's finite size about 0.005)"),
                  ("sneddonCrack", "sneddonCrack (contact unilateral, h = a/d on the crack): the "
                   "error of the opening against Sneddon's (`relL2Error` of "
                   "cases/sneddonCrack/sneddonError.py; the held square costs about 0.0006)"))
              if any(r["case"] == case for r in rows)) +
          ". wallSeconds: the whole frictionSolver run (reading, assembly, factorisation, "
          "iterations, writing; the penny's runs also write their VTK files, which "
          "pennyError.py reads). Status `maxIterations`: the tolerance was not reached (a data "
          "point, not a failure).", ""]
    for case in CASES:
        sel = [r for r in rows if r["case"] == case]
        if not sel:
            continue
        md += ["## " + case, "",
               "| mesh | order | optimizer | tolerance | status | iterations | backSubst. | "
               "factor [s] | wall [s] | ‖D‖/‖Σ‖ | maxExcessST | slip error |",
               "|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in sel:
            md.append("| %s | P%d | %s | %.0e | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                r["mesh"], r["order"], r["optimizer"], r["tolerance"], r["status"],
                fmt(r["iterations"], "i"), fmt(r["backSubstitutions"], "i"),
                fmt(r["factorSeconds"], "s"), fmt(r["wallSeconds"], "s"),
                fmt(r["relResidual"]), fmt(r["maxExcessST"]), fmt(r["slipError"])))
        md.append("")
    if ratio_lines:
        md += ["## Semismooth Newton against the paper's steepest descent", ""] + \
              ["* " + s for s in ratio_lines] + [""]
    md += ["## GetFEM", "", getfem_note(), ""]
    with open(os.path.join(out, "study.md"), "w") as f:
        f.write("\n".join(md))
    plot(out, rows)


def plot(out, rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cases = [c for c in CASES if any(r["case"] == c for r in rows)]
    fig, axes = plt.subplots(1, len(cases), figsize=(6.5 * len(cases), 5.5), squeeze=False)
    axes = axes[0]
    markers = dict(zip(OPTIMIZERS, "os^Dvx"))
    colors = dict(zip(OPTIMIZERS, ["C0", "C1", "C2", "C3", "C4", "C5"]))
    for ax, case in zip(axes, cases):
        for opt in OPTIMIZERS:
            for order in (1, 2):
                # slipError 0 (the reference run itself) is drawn at 1e-16
                pts = [(r["wallSeconds"], max(r["slipError"], 1e-16)) for r in rows
                       if r["case"] == case and r["optimizer"] == opt and r["order"] == order
                       and np.isfinite(r["slipError"])
                       and np.isfinite(r["wallSeconds"])]
                if not pts:
                    continue
                pts.sort()
                x, y = zip(*pts)
                ax.plot(x, y, marker=markers[opt], color=colors[opt],
                        linestyle="-" if order == 1 else "--",
                        markerfacecolor=colors[opt] if order == 1 else "none",
                        label="%s P%d" % (opt, order))
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("frictionSolver wall time [s]")
        ax.set_ylabel("relative L²(Γ) %s error (0 drawn at 1e-16)"
                      % ("opening" if case == "sneddonCrack" else "slip"))
        ax.set_title(case + {"inclinedCrack": " (vs analytic slip)",
                             "paperBenchmark": " (vs finest-mesh reference)",
                             "pennyCrack": " (3D, |slip| vs analytic)",
                             "sneddonCrack": " (opening vs Sneddon)"}[case])
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("What accuracy costs: points are tolerances × meshes")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "study.png"), dpi=110)
    plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[1],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--quick", action="store_true", help="the small sweep (a few minutes)")
    p.add_argument("--cases", nargs="+", choices=CASES, default=CASES, metavar="CASE",
                   help="the cases to sweep (default all: %s)" % " ".join(CASES))
    p.add_argument("--bin", default=os.path.join(REPO, "build", "bin"))
    p.add_argument("--work", default=os.path.join(REPO, "build", "study"))
    p.add_argument("--out", default=None, help="default: WORK/results")
    p.add_argument("--timeout", type=float, default=None,
                   help="wall-time limit of one frictionSolver run [s] (default 60 quick, 300 full)")
    a = p.parse_args()
    binary, work = os.path.abspath(a.bin), os.path.abspath(a.work)
    out = os.path.abspath(a.out or os.path.join(work, "results"))
    timeout = a.timeout or (60.0 if a.quick else 300.0)
    for exe in ("splitFractureNodes", "frictionSolver"):
        if not os.access(os.path.join(binary, exe), os.X_OK):
            sys.exit("frictionStudy: %s not found in %s (use --bin)" % (exe, binary))
    casesdir = os.path.realpath(os.path.join(REPO, "cases"))
    for d in (work, out):
        if os.path.realpath(d).startswith(casesdir + os.sep) or os.path.realpath(d) == casesdir:
            sys.exit("frictionStudy: refusing to write into cases/ (%s)" % d)
    os.makedirs(work, exist_ok=True)
    t_start = time.perf_counter()
    a.cases = [c for c in CASES if c in a.cases]
    runs = plan(a.quick, a.cases)

    bases = {}
    for case, label, v, *_ in runs:
        if (case, label) not in bases:
            bases[(case, label)] = base_case(work, case, label, v)
    # paperBenchmark reference: finest level, per order, semismoothNewton at 1e-12
    pb_levels = sorted({v for c, l, v, *_ in runs if c == "paperBenchmark"})
    finest = pb_levels[-1] if pb_levels else None
    fbase = bases[("paperBenchmark", "n=%d" % finest)] if pb_levels else None
    refs = {}
    for order in ((1, 2) if pb_levels else ()):
        res, tab = run_one(work, fbase, "reference_P%d" % order, order, "semismoothNewton",
                           1e-12, 200, None, binary, timeout)
        if tab is None or res["status"] != "converged":
            sys.exit("frictionStudy: the paperBenchmark reference (n=%d, P%d) failed: %s"
                     % (finest, order, res["status"]))
        refs[order] = tab
    if pb_levels:
        print("reference: paperBenchmark n=%d, semismoothNewton tolerance 1e-12 (P1, P2)"
              % finest)

    rows = []
    hit_max = {}   # (case, mesh, order, opt) -> row of the loosest tolerance that hit the limit
    for i, (case, label, v, order, opt, tol, max_iter) in enumerate(runs):
        key = (case, label, order, opt)
        row = dict(case=case, mesh=label, hOrN=v, order=order, optimizer=opt, tolerance=tol)
        if key in hit_max:
            # a deterministic run that stopped on maxIterations/timeout/diverged at a looser
            # tolerance does exactly the same at a tighter one: reuse it, do not rerun
            prev = hit_max[key]
            row.update({k: prev[k] for k in CSV_COLUMNS[6:]})
            rows.append(row)
            continue
        alpha = sd_alpha(case, v) if opt == "steepestDescent" else None
        tag = "%s_%s_P%d_%s_%g" % (case, label.replace("/", "").replace("=", ""), order, opt, tol)
        res, tab = run_one(work, bases[(case, label)], tag, order, opt, tol, max_iter, alpha,
                           binary, timeout)
        row.update(res)
        err = float("nan")
        if tab is not None:
            if case == "inclinedCrack":
                err = ic_error(tab)
            elif case == "paperBenchmark":
                err = pb_error(tab, refs[order])
            elif case == "sneddonCrack":
                try:
                    err = sneddon_error(os.path.join(work, "runs", tag))
                except RuntimeError as e:
                    print("frictionStudy: %s" % e, file=sys.stderr)
            else:
                try:
                    err = penny_error(os.path.join(work, "runs", tag))
                except RuntimeError as e:
                    print("frictionStudy: %s" % e, file=sys.stderr)
        row["slipError"] = err
        rows.append(row)
        if row["status"] != "converged":
            hit_max[key] = row
        print("[%3d/%d] %-14s %-6s P%d %-16s tol %.0e  %-13s it %6s  wall %7.3f s  err %.3e"
              % (i + 1, len(runs), case, label, order, opt, tol, row["status"],
                 fmt(row["iterations"], "i"), row["wallSeconds"], err), flush=True)

    # The promise: semismoothNewton vs 2000 steepestDescent iterations (alpha 2e-4) on the
    # finest paperBenchmark level of this sweep, P1 (P2 reported as well).
    ratio_lines = []
    for order in ((1, 2) if pb_levels else ()):
        res, tab = run_one(work, fbase, "ratio_sd_P%d" % order, order, "steepestDescent", 1e-14,
                           2000, 2e-4, binary, timeout)
        if tab is None:
            ratio_lines.append("P%d: steepestDescent run failed (%s)" % (order, res["status"]))
            continue
        step = "alpha 2e-4"
        if res["status"] == "diverged":
            # The paper's α was stable on its own mesh (h = 1/40); the stable step shrinks like
            # h², so on a finer mesh it diverges. Then the paper's method runs with the
            # solver's scale-free default step (alphaRelative 1), and the line says so.
            ratio_lines.append("paperBenchmark n=%d P%d: steepestDescent with alpha 2e-4 diverges "
                               "(after %d iterations): the 2000 iterations use alphaRelative 1"
                               % (finest, order, res["iterations"]))
            print(ratio_lines[-1])
            res, tab = run_one(work, fbase, "ratio_sd_rel_P%d" % order, order, "steepestDescent",
                               1e-14, 2000, None, binary, timeout)
            step = "alphaRelative 1"
            if tab is None or res["status"] == "diverged":
                ratio_lines.append("P%d: steepestDescent with alphaRelative 1 failed too (%s): "
                                   "no ratio" % (order, res["status"]))
                continue
        e_sd, t_sd = pb_error(tab, refs[order]), res["wallSeconds"]
        # The loosest tolerance at which each Newton variant reaches that error; the faster
        # of the two counts.
        found = None
        for variant in ("semismoothNewton", "semismoothNewton; variant krylov"):
            for tol in (1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 1e-4, 1e-5, 1e-6, 1e-8, 1e-10, 1e-12):
                tag = "ratio_%s_P%d_%g" % (variant.split()[-1].rstrip(";"), order, tol)
                r2, tab2 = run_one(work, fbase, tag, order, variant, tol, 200, None, binary, timeout)
                if tab2 is not None and pb_error(tab2, refs[order]) <= e_sd:
                    if found is None or r2["wallSeconds"] < found[1]["wallSeconds"]:
                        found = (tol, r2, pb_error(tab2, refs[order]), variant)
                    break
        if found is None:
            ratio_lines.append("P%d: semismoothNewton never reached %.3e" % (order, e_sd))
            continue
        tol, r2, e2, variant = found
        line = ("paperBenchmark n=%d P%d: %d steepestDescent iterations (%s): slip "
                "error %.3e, ‖D‖/‖Σ‖ %.3g, %.3f s; %s (tolerance %g, %d iterations) "
                "reaches %.3e in %.3f s: semismoothNewton is %.0f× faster"
                % (finest, order, res["iterations"], step, e_sd, res["relResidual"], t_sd, variant,
                   tol, r2["iterations"], e2, r2["wallSeconds"], t_sd / r2["wallSeconds"]))
        ratio_lines.append(line)
        if order == 1:
            print("semismoothNewton is %.0f× faster  (%s)" % (t_sd / r2["wallSeconds"], line))
        else:
            print(line)

    total = time.perf_counter() - t_start
    mode = ("quick" if a.quick else "full") + \
        ("" if a.cases == CASES else " (cases %s)" % ", ".join(a.cases))
    write_outputs(out, rows, ratio_lines, mode, total,
                  "semismoothNewton at tolerance 1e-12 on n = %d (same order)" % finest
                  if pb_levels else None)
    bad = [r for r in rows if r["status"].startswith(("crash", "timeout"))]
    print("wrote %s/study.csv (%d rows), study.md, study.png in %.1f s%s"
          % (out, len(rows), total, "; %d runs crashed or timed out" % len(bad) if bad else ""))


if __name__ == "__main__":
    main()
