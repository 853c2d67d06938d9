#!/usr/bin/python3
"""plotFracture: plots of a solved case's fracture tables and convergence history.

Figure 1, per fracture (default <case>/postProcessing/fracture_<name>.png):
  top:    for a Coulomb fracture (law coulomb or coulombCohesion, mu_f > 0) with compressed
          nodes:
          the slip tendency ST = |tau| / -sigma_n along the arclength s, one curve per time,
          with the friction coefficient mu_f of constant/fractureProperties as a dashed line
          (Coulomb: ST <= mu_f, equality where the fracture slips). Otherwise (tresca,
          frictionless, mu_f = 0, or a fracture in tension, where ST and mu_f mean nothing): the
          tractions sigma_n and tau [Pa] along s.
  bottom: the accumulated slip [m] along s, one curve per time.
Tips (state 'tip': a single node, no traction) are left out of the traction and ST curves;
their slip, 0 (the jump is held there), is drawn.
Figure 2 (default <case>/postProcessing/convergence.png, when postProcessing/convergence.dat
exists): J and the relative residual |D|/|Sigma| against the iteration, log scale, one curve
per time step.

Input: <case>/<time>/fractures/<name>.dat as frictionSolver writes it (README.md,
"frictionSolver": a "# s x y slip ..." header line, a "# status ..." line, then rows; "nan"
in a tip's traction columns) and <case>/postProcessing/convergence.dat (columns time
iteration J relResidual stepNorm after a "#" header). Time folders are the numeric folder
names other than 0.

Usage:
  plotFracture.py -case DIR [-fracture NAME] [-times t1,t2,...] [-o out.png]
                  [-convergence out.png] [-noConvergence] [-help]
  -fracture   one fracture (default: every fracture found in the time folders)
  -times      times to plot, as numbers (default: every time folder)
  -o          output of the fracture figure (needs -fracture when there are several)
Sample run:
  /usr/bin/python3 utilities/plotFracture/plotFracture.py -case cases/paperBenchmark
Prints one line per figure written, saying what its top panel shows. Errors (missing case,
no time folders, unknown fracture or time) go to stderr, exit 1.
Run it with Debian's /usr/bin/python3, which sees python3-matplotlib.
"""
import argparse
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402


class PlotError(Exception):
    """A problem with the user's case or options: reported on stderr, exit status 1."""


def isNumber(name):
    try:
        float(name)
        return True
    except ValueError:
        return False


def timeFolders(case):
    """Numeric folder names other than 0, in increasing time."""
    names = [d for d in os.listdir(case)
             if isNumber(d) and os.path.isdir(os.path.join(case, d)) and float(d) != 0.0]
    return sorted(names, key=float)


def readTable(path):
    """Columns of a fracture table by header name, the status comment and the rows."""
    with open(path) as f:
        lines = f.read().splitlines()
    if not lines or not lines[0].startswith("#"):
        raise PlotError(f"{path}:1: expected the header '# s x y slip ...'")
    names = lines[0][1:].split()
    for required in ("s", "slip", "ST", "state"):
        if required not in names:
            raise PlotError(f"{path}:1: the header has no column '{required}'")
    status = ""
    cols = {n: [] for n in names}
    for number, line in enumerate(lines[1:], start=2):
        if line.startswith("#"):
            status = status or line[1:].strip()
            continue
        if not line.strip():
            continue
        items = line.split()
        if len(items) != len(names):
            raise PlotError(f"{path}:{number}: {len(items)} columns, the header names "
                            f"{len(names)}")
        for n, v in zip(names, items):
            try:
                cols[n].append(v if n == "state" else float(v))
            except ValueError:
                raise PlotError(f"{path}:{number}: column {n}: '{v}' is not a number")
    return cols, status


def stripComments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def fractureEntry(case, fracture, key):
    """The value of 'key' in the fracture's sub-dictionary of constant/fractureProperties,
    as a string, or None."""
    path = os.path.join(case, "constant", "fractureProperties")
    try:
        with open(path) as f:
            text = stripComments(f.read())
    except OSError:
        return None
    block = re.search(r"(?:^|[\s;}])" + re.escape(fracture) + r"\s*\{([^{}]*)\}", text)
    if not block:
        return None
    m = re.search(r"(?:^|[\s;])" + key + r"\s+([^;\s]+)\s*;", block.group(1))
    return m.group(1) if m else None


def frictionCoefficient(case, fracture):
    """mu_f of the fracture's sub-dictionary of constant/fractureProperties, or None."""
    value = fractureEntry(case, fracture, "frictionCoefficient")
    try:
        return float(value) if value is not None else None
    except ValueError:
        return None


COULOMB_LAWS = ("coulomb", "coulombCohesion")


def statusWord(status):
    """'converged', 'maxIterations', ... from '# status <word> iterations ...'."""
    m = re.match(r"status\s+(\S+)", status)
    return m.group(1) if m else ""


def plotFracture(case, name, times, out):
    """Draw figure 1; returns what the top panel shows ("slip tendency" or "tractions")."""
    law = fractureEntry(case, name, "law")
    mu = frictionCoefficient(case, name)
    tables = []
    for t in times:
        cols, status = readTable(os.path.join(case, t, "fractures", name + ".dat"))
        tables.append((t, cols, statusWord(status)))
    # ST = |tau| / -sigma_n and the line ST = mu_f mean something only for a Coulomb law at
    # compressed nodes; a tip (no traction) counts for nothing.
    compressed = any(state in ("stick", "slip") and sigmaN < 0
                     for _, cols, _ in tables
                     for state, sigmaN in zip(cols["state"], cols.get("sigmaN", [])))
    showST = law in COULOMB_LAWS and compressed and (mu is None or mu > 0)
    fig, (axTop, axSlip) = plt.subplots(2, 1, figsize=(8, 7.5), sharex=True)
    colors = plt.cm.viridis([0.15 + 0.7 * i / max(1, len(times) - 1) for i in range(len(times))])
    for (t, cols, word), color in zip(tables, colors):
        label = f"t = {t}" + (f" ({word})" if word and word != "converged" else "")
        keep = [i for i, state in enumerate(cols["state"]) if state != "tip"]
        s = [cols["s"][i] for i in keep]
        if showST:
            axTop.plot(s, [cols["ST"][i] for i in keep], ".-", color=color, ms=3, lw=1, label=label)
        else:
            for key, symbol, style in (("sigmaN", r"$\sigma_n$", ".-"), ("tau", r"$\tau$", "x--")):
                if key in cols:
                    axTop.plot(s, [cols[key][i] for i in keep], style, color=color, ms=3, lw=1,
                               label=f"{symbol}, {label}")
        axSlip.plot(cols["s"], cols["slip"], ".-", color=color, ms=3, lw=1, label=label)
    if showST:
        if mu is not None:
            axTop.axhline(mu, color="firebrick", ls="--", lw=1.2, label=f"$\\mu_f$ = {mu:g}")
        axTop.set_ylabel(r"slip tendency ST = $|\tau| / (-\sigma_n)$")
    else:
        axTop.set_ylabel(r"traction $\sigma_n$, $\tau$ [Pa]")
    axTop.set_title(f"{os.path.basename(os.path.abspath(case))}: fracture '{name}'"
                    + (f" (law {law})" if law else ""))
    axTop.grid(True, alpha=0.3)
    axTop.legend(fontsize=8)
    axSlip.set_xlabel("arclength s [m]")
    axSlip.set_ylabel("slip [m]")
    axSlip.grid(True, alpha=0.3)
    axSlip.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return "slip tendency" if showST else "tractions"


def readConvergence(path):
    """{time: (iterations, J, relResidual)} from convergence.dat, in file order."""
    runs = {}
    with open(path) as f:
        for number, line in enumerate(f, start=1):
            if line.startswith("#") or not line.strip():
                continue
            items = line.split()
            if len(items) < 4:
                raise PlotError(f"{path}:{number}: expected 'time iteration J relResidual "
                                f"stepNorm'")
            try:
                t, it, J, rel = items[0], int(float(items[1])), float(items[2]), float(items[3])
            except ValueError:
                raise PlotError(f"{path}:{number}: not a number in '{line.strip()}'")
            run = runs.setdefault(t, ([], [], []))
            run[0].append(it)
            run[1].append(J)
            run[2].append(rel)
    return runs


def plotConvergence(case, path, times, out):
    runs = readConvergence(path)
    if times is not None:
        wanted = {float(t) for t in times}
        runs = {t: r for t, r in runs.items() if float(t) in wanted}
    if not runs:
        raise PlotError(f"{path}: no iterations recorded for the chosen times")
    fig, (axJ, axR) = plt.subplots(2, 1, figsize=(8, 7.5), sharex=True)
    keys = sorted(runs, key=float)
    colors = plt.cm.viridis([0.15 + 0.7 * i / max(1, len(keys) - 1) for i in range(len(keys))])
    for t, color in zip(keys, colors):
        it, J, rel = runs[t]
        # Log axes cannot show 0 (an exact solve): those points are left out.
        axJ.semilogy([i for i, v in zip(it, J) if v > 0], [v for v in J if v > 0],
                     ".-", color=color, ms=3, lw=1, label=f"t = {t}")
        axR.semilogy([i for i, v in zip(it, rel) if v > 0], [v for v in rel if v > 0],
                     ".-", color=color, ms=3, lw=1, label=f"t = {t}")
    axJ.set_ylabel("J")
    axJ.set_title(f"{os.path.basename(os.path.abspath(case))}: convergence of the control "
                  "iteration")
    axR.set_ylabel(r"relResidual $\|D\|_M / \|\Sigma\|_M$")
    axR.set_xlabel("iteration")
    axR.xaxis.set_major_locator(MaxNLocator(integer=True))
    for ax in (axJ, axR):
        ax.grid(True, which="both", alpha=0.3)
        if len(keys) <= 12:
            ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def main(argv):
    # OpenFOAM-style single-dash options: -help as well as -h.
    ap = argparse.ArgumentParser(prog="plotFracture", description=__doc__.split("\n")[0],
                                 add_help=False)
    ap.add_argument("-h", "-help", "--help", action="help", help="print this help and exit")
    ap.add_argument("-case", required=True, help="case folder")
    ap.add_argument("-fracture", help="fracture name (default: every fracture)")
    ap.add_argument("-times", help="comma-separated times (default: every time folder)")
    ap.add_argument("-o", dest="out", help="output PNG of the fracture figure")
    ap.add_argument("-convergence", help="output PNG of the convergence figure")
    ap.add_argument("-noConvergence", action="store_true", help="no convergence figure")
    a = ap.parse_args(argv)

    case = a.case
    if not os.path.isdir(case):
        raise PlotError(f"{case}: no such case folder")
    available = timeFolders(case)
    if not available:
        raise PlotError(f"{case}: no time folders (run frictionSolver first)")
    if a.times:
        times = []
        for item in a.times.split(","):
            try:
                value = float(item)
            except ValueError:
                raise PlotError(f"-times: '{item}' is not a number")
            match = [t for t in available if math.isclose(float(t), value, rel_tol=1e-9,
                                                           abs_tol=1e-12)]
            if not match:
                raise PlotError(f"{case}: no time folder {item} (there are: "
                                f"{' '.join(available)})")
            times.append(match[0])
    else:
        times = available

    found = set()
    for t in times:
        folder = os.path.join(case, t, "fractures")
        if os.path.isdir(folder):
            found |= {f[:-4] for f in os.listdir(folder) if f.endswith(".dat")}
    if a.fracture:
        if a.fracture not in found:
            raise PlotError(f"{case}: unknown fracture '{a.fracture}' (fractures: "
                            f"{' '.join(sorted(found)) or 'none'})")
        names = [a.fracture]
    else:
        if not found:
            raise PlotError(f"{case}: no fracture tables in the time folders")
        names = sorted(found)
        if a.out and len(names) > 1:
            raise PlotError(f"-o: {len(names)} fractures ({' '.join(names)}); choose one "
                            "with -fracture")
    for name in names:
        missing = [t for t in times
                   if not os.path.isfile(os.path.join(case, t, "fractures", name + ".dat"))]
        if missing:
            raise PlotError(f"{case}: fracture '{name}' has no table at time(s) "
                            f"{' '.join(missing)}")

    post = os.path.join(case, "postProcessing")
    written = []
    for name in names:
        out = a.out or os.path.join(post, f"fracture_{name}.png")
        os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
        shows = plotFracture(case, name, times, out)
        written.append(f"{out} ({shows} and slip)")
    history = os.path.join(post, "convergence.dat")
    if not a.noConvergence:
        if os.path.isfile(history):
            out = a.convergence or os.path.join(post, "convergence.png")
            os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
            plotConvergence(case, history, times if a.times else None, out)
            written.append(out)
        elif a.convergence:
            raise PlotError(f"{history}: not found (needed for -convergence)")
    for w in written:
        print(f"Written {w}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except PlotError as e:
        print(f"plotFracture: error: {e}", file=sys.stderr)
        sys.exit(1)
    except OSError as e:
        print(f"plotFracture: error: {e}", file=sys.stderr)
        sys.exit(1)
