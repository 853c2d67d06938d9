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
  bottom: the accumulated slip [m] along s, one curve per time; with fractures that open
          (an 'opening' column: contact unilateral) a third panel, the opening g [m]; with a
          fluid pressure (columns 'pressure sigmaNEffective': fracturePressure, faultPressure)
          a last panel, p and sigma'_n = sigma_n + p [Pa] along s, and ST and the check for
          compressed nodes then use sigma'_n.
Tips and junction ends (states 'tip', 'junction': no jump, no recovered traction; the table
gives the body's stress there, a stress concentration that grows under refinement) are left
out of the traction and ST curves; their slip, 0 (the jump is held there), is drawn.
Figure 2 (default <case>/postProcessing/convergence.png, when postProcessing/convergence.dat
exists): J and the relative residual |D|/|Sigma| against the iteration, log scale, one curve
per time step.

Input: <case>/<time>/fractures/<name>.dat as frictionSolver writes it (README.md,
"frictionSolver": a "# s x y slip ..." header line, a "# status ..." line, then rows; columns
by name, a "nan" of older tables read as a missing value) and <case>/postProcessing/convergence.dat (columns time
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

3D fracture tables (header "# x y z nx ny nz slip1 slip2 ...", README.md "frictionSolver"):
the dimension is told from the header. Per fault, at the last of the chosen times:
  maps (default <case>/postProcessing/fracture_<name>.png) in the fault's mean plane (normal n:
  the table's "# frame n (..) ..." line on a flat fault, the normalised mean of the nodes'
  normals on a curved one), from the centroid of the nodes: horizontal axis along strike,
  vertical axis up dip (the shallow end at the top; the fault seen from its hanging wall; a
  horizontal fault in map view, x right, y up), strike and dip as README.md ("Fluid
  pressure") defines them, computed from n; z of the plane on a right-hand axis (exact on a
  flat fault), the strike, its azimuth and the dip angle in the title. The nodes are
  projected on that plane and triangulated (Delaunay: the convex hull of the projected
  nodes, flat border triangles removed):
    slip magnitude [m] with arrows of the hanging wall's slip relative to the footwall
    (slipX slipY slipZ, their sign as slipStrike slipDip's, projected on the map axes),
    ST over the non-tip nodes, and the node states (tip, stick, slip, open) as markers; with
    a fluid pressure (columns pressure, sigmaNEffective) two more maps, p and sigma'_n, each
    with the outline of the slipping nodes (two rows of maps);
  profile (default <case>/postProcessing/fracture_<name>_profile.png): slipMagnitude,
  sigmaN, tauMagnitude and ST (and opening, pressure, sigmaNEffective where the tables have
  them) along segments, one curve per chosen time, sampled by linear interpolation on the
  triangulation (tractions on the triangulation of the non-tip nodes). By default two
  segments through the node of largest slip at the last time (the centroid when nothing
  slips), each across the whole fault (to the triangulation's border): along strike
  (left column, against the map's horizontal coordinate) and along dip from the deep end up
  (right column, against the map's vertical coordinate: up dip to the right, with z on top).
  -line x0,y0,z0:x1,y1,z1 (two points in m, projected on the map plane) gives one segment
  instead, against the distance from its first point. Samples off the triangulated surface
  are left out of the plot (nan in the CSV).
  -profile out.png, -profileCsv out.csv (time,distance,x,y,z,slipMagnitude,sigmaN,
  tauMagnitude,ST, then pressure,sigmaNEffective where the tables have them; x y z the sample
  point on the segment, distance from its first point; the default pair adds a first column
  profile, strike or dip), -samples N (default 201 per segment).
The line printed for the maps names their axes ("axes: along strike (..) right, up dip (..)
up, from the centroid (..)"). No axis of any figure uses an offset (a normal stress of
-2.87e7 Pa is labelled as such, with a 1eN multiplier where needed).
Every table is read and checked before any file is written, and each file is written under
a temporary name and renamed: a failed run leaves no partial figure.
"""
import argparse
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
# No axis offsets: a normal stress of -2.87e7 Pa varying by 8e3 Pa drawn as offset ticks of
# +-8 000 makes noise look like structure; plain values (with a 1eN multiplier where needed)
# keep the magnitude in sight. rcParams reach every scalar axis: maps, colorbars, twins.
matplotlib.rcParams["axes.formatter.useoffset"] = False
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402


class PlotError(Exception):
    """A problem with the user's case or options: reported on stderr, exit status 1."""


def saveFigure(fig, out):
    """Write the figure under a temporary name in out's folder, then rename it to out: a run
    stopped or failing while drawing leaves no partial file. The format is the one savefig
    would take from out's name."""
    ext = os.path.splitext(out)[1][1:].lower()
    fmt = ext or matplotlib.rcParams["savefig.format"]
    supported = fig.canvas.get_supported_filetypes()
    if fmt not in supported:
        raise PlotError(f"{out}: unknown image format '{fmt}' (known: "
                        f"{' '.join(sorted(supported))})")
    folder, base = os.path.split(os.path.abspath(out))
    tmp = os.path.join(folder, f".{base}.{os.getpid()}.tmp")
    try:
        fig.savefig(tmp, dpi=120, format=fmt)
        os.replace(tmp, out)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


def writeTextAtomically(out, text):
    folder, base = os.path.split(os.path.abspath(out))
    tmp = os.path.join(folder, f".{base}.{os.getpid()}.tmp")
    try:
        with open(tmp, "w") as f:
            f.write(text)
        os.replace(tmp, out)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


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
    """Draw figure 1; returns what the top panel shows ("slip tendency" or "tractions"),
    whether it has the opening's panel and whether it has the fluid pressure's panel."""
    law = fractureEntry(case, name, "law")
    mu = frictionCoefficient(case, name)
    tables = []
    for t in times:
        cols, status = readTable(os.path.join(case, t, "fractures", name + ".dat"))
        tables.append((t, cols, statusWord(status)))
    # ST = |tau| / -sigma_n and the line ST = mu_f mean something only for a Coulomb law at
    # compressed nodes; a tip or junction end (no recovered traction) counts for nothing.
    # With a fluid pressure (columns pressure, sigmaNEffective) the law and ST act on the
    # effective normal stress sigma'_n = sigma_n + p: a node is compressed where sigma'_n < 0.
    pressure = any("pressure" in cols and "sigmaNEffective" in cols for _, cols, _ in tables)
    normal = "sigmaNEffective" if pressure else "sigmaN"
    compressed = any(state in ("stick", "slip") and sigmaN < 0
                     for _, cols, _ in tables
                     for state, sigmaN in zip(cols["state"], cols.get(normal, [])))
    showST = law in COULOMB_LAWS and compressed and (mu is None or mu > 0)
    opening = any("opening" in cols for _, cols, _ in tables)
    panels = 2 + opening + pressure
    fig, axes = plt.subplots(panels, 1, figsize=(8, 7.5 + 2.5 * (panels - 2)), sharex=True)
    axTop, axSlip = axes[0], axes[1]
    axOpen = axes[2] if opening else None
    axPress = axes[-1] if pressure else None
    colors = plt.cm.viridis([0.15 + 0.7 * i / max(1, len(times) - 1) for i in range(len(times))])
    for (t, cols, word), color in zip(tables, colors):
        label = f"t = {t}" + (f" ({word})" if word and word != "converged" else "")
        keep = [i for i, state in enumerate(cols["state"]) if state not in ("tip", "junction")]
        s = [cols["s"][i] for i in keep]
        if showST:
            axTop.plot(s, [cols["ST"][i] for i in keep], ".-", color=color, ms=3, lw=1, label=label)
        else:
            for key, symbol, style in (("sigmaN", r"$\sigma_n$", ".-"), ("tau", r"$\tau$", "x--")):
                if key in cols:
                    axTop.plot(s, [cols[key][i] for i in keep], style, color=color, ms=3, lw=1,
                               label=f"{symbol}, {label}")
        axSlip.plot(cols["s"], cols["slip"], ".-", color=color, ms=3, lw=1, label=label)
        if opening and "opening" in cols:
            axOpen.plot(cols["s"], cols["opening"], ".-", color=color, ms=3, lw=1, label=label)
        if pressure and "pressure" in cols and "sigmaNEffective" in cols:
            # p on every node (a tip has one too); sigma'_n where there is a traction.
            axPress.plot(cols["s"], cols["pressure"], ".-", color=color, ms=3, lw=1,
                         label=f"$p$, {label}")
            axPress.plot(s, [cols["sigmaNEffective"][i] for i in keep], "x--", color=color,
                         ms=3, lw=1, label=f"$\\sigma'_n$, {label}")
    if showST:
        if mu is not None:
            axTop.axhline(mu, color="firebrick", ls="--", lw=1.2, label=f"$\\mu_f$ = {mu:g}")
        axTop.set_ylabel(r"slip tendency ST = $|\tau| / (-\sigma'_n)$" if pressure
                         else r"slip tendency ST = $|\tau| / (-\sigma_n)$")
    else:
        axTop.set_ylabel(r"traction $\sigma_n$, $\tau$ [Pa]")
    axTop.set_title(f"{os.path.basename(os.path.abspath(case))}: fracture '{name}'"
                    + (f" (law {law})" if law else ""))
    axTop.grid(True, alpha=0.3)
    axTop.legend(fontsize=8)
    axSlip.set_ylabel("slip [m]")
    axSlip.grid(True, alpha=0.3)
    axSlip.legend(fontsize=8)
    if opening:
        axOpen.set_ylabel("opening g [m]")
        axOpen.grid(True, alpha=0.3)
        axOpen.legend(fontsize=8)
    if pressure:
        axPress.set_ylabel(r"fluid pressure $p$, $\sigma'_n = \sigma_n + p$ [Pa]")
        axPress.grid(True, alpha=0.3)
        axPress.legend(fontsize=8)
    axes[-1].set_xlabel("arclength s [m]")
    fig.tight_layout()
    saveFigure(fig, out)
    plt.close(fig)
    return ("slip tendency" if showST else "tractions"), opening, pressure


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
    saveFigure(fig, out)
    plt.close(fig)


# ---- 3D fracture tables: maps over the fault surface and a profile along a segment ----

STATES = ("tip", "stick", "slip", "open", "junction")  # junction: a held end where faults meet
COLUMNS_3D = ("x", "y", "z", "nx", "ny", "nz", "slip1", "slip2", "slipX", "slipY", "slipZ",
              "slipMagnitude", "sigmaN", "tauMagnitude", "ST", "state")
# Columns that are finite on every row (every column is, but tables of older versions had nan
# tractions at tips, and the tips are left out of the traction maps anyway).
FINITE_3D = ("x", "y", "z", "nx", "ny", "nz", "slip1", "slip2", "slipX", "slipY", "slipZ",
             "slipMagnitude")
FRAME_FLAT = re.compile(r"frame\s+n\s*\(([^()]*)\)\s*t1\s*\(([^()]*)\)\s*t2\s*\(([^()]*)\)\s*$")


def headerNames(path):
    """The column names of a fracture table's first line ('# s x y ...' or '# x y z ...')."""
    with open(path) as f:
        first = f.readline()
    return first[1:].split() if first.startswith("#") else []


def is3dTable(path):
    return headerNames(path)[:3] == ["x", "y", "z"]


def strikeDip(n):
    """The strike and down-dip unit vectors of a plane of unit normal n, as README.md ("Fluid
    pressure") defines them and the solver's strikeDipBasis computes them: dip the steepest
    way down the plane, strike horizontal in it with the plane dipping to its right (seen from
    above, dip is strike turned clockwise by 90 degrees), whichever side n points to; a
    vertical plane has dip = -z and the strike with x > 0 (or along +y); a horizontal one
    strike = x, dip = -y."""
    n = np.asarray(n, dtype=float)
    down = np.array([0.0, 0.0, -1.0]) + n[2] * n
    if abs(n[2]) >= 1 - 1e-12 or np.linalg.norm(down) < 1e-12:
        return np.array([1.0, 0.0, 0.0]), np.array([0.0, -1.0, 0.0])
    if abs(n[2]) <= 1e-12:
        strike = np.array([-n[1], n[0], 0.0])
        strike /= np.linalg.norm(strike)
        if strike[0] < 0 or (strike[0] == 0 and strike[1] < 0):
            strike = -strike
        return strike, np.array([0.0, 0.0, -1.0])
    dip = down / np.linalg.norm(down)
    strike = np.array([-dip[1], dip[0], 0.0])
    return strike / np.linalg.norm(strike), dip


def hangingWallSign(normals):
    """Per node, +1 where the table's slip (the + side's, n_Gamma from the + side to the - one)
    is the hanging wall's relative to the footwall, -1 where it is the footwall's: the rule of
    the tables' slipStrike, slipDip (the hanging wall is the side above the fault, of a
    vertical fault the side to the right of strike)."""
    sign = np.empty(len(normals))
    for i, n in enumerate(normals):
        strike, dip = strikeDip(n)
        sign[i] = 1.0 if n @ np.cross(dip, strike) < 0 else -1.0
    return sign


def readTable3d(path):
    """A 3D fracture table (SPEC: header, '# status ...', '# frame ...', rows) as a dict:
    numpy arrays by column name, 'state' a list, 'status' and 'frame' ((n, t1, t2) of a flat
    fault, None when the frame is per node)."""
    with open(path) as f:
        lines = f.read().splitlines()
    names = lines[0][1:].split()
    for required in COLUMNS_3D:
        if required not in names:
            raise PlotError(f"{path}:1: the header has no column '{required}' (a 3D table has "
                            f"'# {' '.join(COLUMNS_3D[:-1])} ... state')")
    status, frame = "", None
    rows = []
    for number, line in enumerate(lines[1:], start=2):
        if line.startswith("#"):
            text = line[1:].strip()
            if text.startswith("frame"):
                if text.startswith("frame per node"):
                    frame = None
                    continue
                m = FRAME_FLAT.match(text)
                try:
                    vectors = [np.array([float(v) for v in g.split()]) for g in m.groups()]
                except (AttributeError, ValueError):
                    vectors = []
                if len(vectors) != 3 or any(v.shape != (3,) or not np.all(np.isfinite(v))
                                            for v in vectors):
                    raise PlotError(f"{path}:{number}: expected '# frame n (nx ny nz) t1 "
                                    f"(ax ay az) t2 (bx by bz)' or '# frame per node: ...'")
                frame = tuple(v / np.linalg.norm(v) for v in vectors)
            else:
                status = status or text
            continue
        if not line.strip():
            continue
        items = line.split()
        if len(items) != len(names):
            raise PlotError(f"{path}:{number}: {len(items)} columns, the header names "
                            f"{len(names)}")
        row = {}
        for n, v in zip(names, items):
            if n == "state":
                if v not in STATES:
                    raise PlotError(f"{path}:{number}: state '{v}' is not one of "
                                    f"{', '.join(STATES)}")
                row[n] = v
                continue
            try:
                row[n] = float(v)
            except ValueError:
                raise PlotError(f"{path}:{number}: column {n}: '{v}' is not a number")
            if n in FINITE_3D and not math.isfinite(row[n]):
                raise PlotError(f"{path}:{number}: column {n}: '{v}' is not finite")
        rows.append(row)
    if not rows:
        raise PlotError(f"{path}: no rows (a fracture table has one row per fracture node)")
    table = {n: np.array([r[n] for r in rows]) for n in names if n != "state"}
    table["state"] = [r["state"] for r in rows]
    table["status"] = status
    table["frame"] = frame
    table["path"] = path
    return table


class MapPlane:
    """The plane the maps are drawn in: origin the nodes' centroid, normal n (the table's frame
    on a flat fault, the mean of the nodes' normals on a curved one), map axes u along strike
    (to the right) and v up dip (up: the shallow end at the top), so that a dipping fault is
    seen from its hanging wall and a horizontal one from above (x right, y up). z on the plane
    is z0 + v * up[2]."""

    def __init__(self, table):
        pos = np.column_stack([table["x"], table["y"], table["z"]])
        self.origin = pos.mean(axis=0)
        if table["frame"] is not None:
            self.n = table["frame"][0]
            self.flat = True
        else:
            # Normals all point from the + side to the - side, so their sum is a mean
            # direction; it vanishes only for a surface that turns back on itself.
            total = np.column_stack([table["nx"], table["ny"], table["nz"]]).sum(axis=0)
            if np.linalg.norm(total) < 1e-6 * len(pos):
                raise PlotError(f"{table['path']}: the nodes' normals cancel out: the fault "
                                "has no mean plane to draw its maps in")
            self.n = total / np.linalg.norm(total)
            self.flat = False
        self.strike, self.dip = strikeDip(self.n)
        self.up = -self.dip
        # The angle between the plane and the horizontal, and the strike's azimuth from x
        # towards y, in (-180, 180].
        self.dipAngle = math.degrees(math.acos(min(1.0, abs(self.n[2]))))
        self.azimuth = math.degrees(math.atan2(self.strike[1], self.strike[0]))
        self.horizontal = self.up[2] < 1e-12

    def project(self, points):
        d = np.atleast_2d(points) - self.origin
        return d @ self.strike, d @ self.up

    def point(self, u, v):
        """The 3D points of map coordinates u, v (on the plane)."""
        return (self.origin + np.outer(np.atleast_1d(u), self.strike)
                + np.outer(np.atleast_1d(v), self.up))

    def zOf(self, v):
        return self.origin[2] + v * self.up[2]

    def vOf(self, z):
        return (z - self.origin[2]) / self.up[2]

    def describe(self):
        def vec(v):  # round-off (a frame written to 10 digits) shown as 0
            return "(" + " ".join(f"{c:.3g}" for c in np.where(np.abs(v) < 1e-9, 0.0, v)) + ")"
        kind = "the fault's frame" if self.flat else "curved: the nodes' mean normal"
        if self.horizontal:
            where = f"horizontal at z = {self.origin[2]:.6g} m: map view, x right, y up"
        else:
            where = (f"strike {vec(self.strike)}, {self.azimuth:.1f}° from x towards y; dip "
                     f"{self.dipAngle:.1f}° (down dip {vec(self.dip)});\nseen from the "
                     "hanging wall, shallow end up")
        return f"{where}; n = {vec(self.n)} ({kind})"

    def axesText(self):
        """The map axes as a parsable phrase for the line printed per figure."""
        vec = lambda v: "(" + " ".join(f"{c:.6g}" for c in v + 0.0) + ")"  # noqa: E731
        return (f"axes: along strike {vec(self.strike)} right, up dip {vec(self.up)} up, from "
                f"the centroid {vec(self.origin)}")


def triangulate(u, v, path, what):
    """Delaunay triangulation of the projected nodes, flat border triangles masked (nearly
    collinear nodes on the border of a disc or a rectangle would give slivers)."""
    if len(u) < 3:
        raise PlotError(f"{path}: {len(u)} {what}: a map needs at least 3")
    try:
        tri = mtri.Triangulation(u, v)
    except (RuntimeError, ValueError):
        raise PlotError(f"{path}: the {what} lie on one line in the map plane: they do not "
                        "span a surface")
    tri.set_mask(mtri.TriAnalyzer(tri).get_flat_tri_mask(min_circle_ratio=0.01))
    return tri


class FaultMaps:
    """One table's nodes in the map plane with the triangulations the maps and the profile
    use: all nodes (slip, zero at tips) and the non-tip nodes with finite tractions."""

    def __init__(self, table, plane):
        self.table = table
        pos = np.column_stack([table["x"], table["y"], table["z"]])
        self.u, self.v = plane.project(pos)
        # The arrows: the hanging wall's slip relative to the footwall (as slipStrike, slipDip),
        # so that a normal fault's arrows point down dip whichever side n_Gamma points to.
        normals = np.column_stack([table["nx"], table["ny"], table["nz"]])
        slip = np.column_stack([table["slipX"], table["slipY"], table["slipZ"]])
        slip *= hangingWallSign(normals)[:, None]
        self.slipU, self.slipV = slip @ plane.strike, slip @ plane.up
        self.tri = triangulate(self.u, self.v, table["path"], "nodes")
        # The projection on one plane is one-to-one only where the surface does not turn
        # past 90 degrees from it; nodes projected onto others drop out of the triangulation.
        turned = int(np.count_nonzero(normals @ plane.n <= 0))
        used = np.zeros(len(self.u), dtype=bool)
        used[self.tri.get_masked_triangles().ravel()] = True
        self.foldWarning = None
        if turned or not used.all():
            self.foldWarning = (f"{table['path']}: the fault folds over itself in its mean plane "
                                f"({turned} node normals at 90 degrees or more from it, "
                                f"{np.count_nonzero(~used)} nodes on top of others): its maps "
                                "and profile overlap there")
        # Tips and held ends where faults meet (junction) have no recovered traction.
        self.keep = np.array([s not in ("tip", "junction") for s in table["state"]])
        # A fluid pressure (columns pressure and sigmaNEffective): p is drawn over every node
        # when it is finite at each (the solver writes it at tips too), sigma'_n as a traction.
        self.pressure = "pressure" in table and "sigmaNEffective" in table
        for key in ("sigmaN", "tauMagnitude", "ST") + (("sigmaNEffective",) if self.pressure
                                                        else ()):
            self.keep &= np.isfinite(table[key])
        self.pressureEverywhere = self.pressure and bool(np.isfinite(table["pressure"]).all())
        self.tractionTri = None
        if self.keep.sum() >= 3:
            try:
                self.tractionTri = triangulate(self.u[self.keep], self.v[self.keep],
                                               table["path"], "nodes with tractions")
            except PlotError:
                self.tractionTri = None

    def sample(self, u, v):
        """slipMagnitude, sigmaN, tauMagnitude, ST (and opening, pressure, sigmaNEffective where
        the table has them) at the map points, nan off the surface."""
        # A point on the border (the default segment ends on border nodes) may be found
        # outside by round-off: such points are looked up again a hair (1e-9 of the map's
        # size) towards the centroid.
        size = max(np.ptp(self.u), np.ptp(self.v))
        cu, cv = self.u.mean(), self.v.mean()

        def interp(tri, values):
            f = mtri.LinearTriInterpolator(tri, values)
            out = np.ma.filled(f(u, v), np.nan)
            miss = ~np.isfinite(out)
            if miss.any():
                du, dv = cu - u[miss], cv - v[miss]
                step = 1e-9 * size / np.maximum(np.hypot(du, dv), 1e-300)
                out[miss] = np.ma.filled(f(u[miss] + step * du, v[miss] + step * dv), np.nan)
            return out
        out = {"slipMagnitude": interp(self.tri, self.table["slipMagnitude"])}
        if "opening" in self.table:  # fractures that open (contact unilateral)
            out["opening"] = interp(self.tri, self.table["opening"])
        tractions = ("sigmaN", "tauMagnitude", "ST")
        if self.pressure:
            tractions += ("sigmaNEffective",)
            if self.pressureEverywhere:
                out["pressure"] = interp(self.tri, self.table["pressure"])
            else:
                tractions += ("pressure",)
        for key in tractions:
            out[key] = (interp(self.tractionTri, self.table[key][self.keep])
                        if self.tractionTri is not None else np.full(np.shape(u), np.nan))
        return out


def parseLine(text):
    """'x0,y0,z0:x1,y1,z1' -> two points."""
    form = "expected x0,y0,z0:x1,y1,z1 (two points in m)"
    parts = text.split(":")
    if len(parts) != 2:
        raise PlotError(f"-line: {form}, got '{text}'")
    points = []
    for part in parts:
        items = part.split(",")
        try:
            p = np.array([float(c) for c in items])
        except ValueError:
            raise PlotError(f"-line: {form}, got '{text}'")
        if p.shape != (3,) or not np.all(np.isfinite(p)):
            raise PlotError(f"-line: {form}, got '{text}'")
        points.append(p)
    if np.linalg.norm(points[1] - points[0]) == 0:
        raise PlotError(f"-line: the two points of '{text}' coincide")
    return points[0], points[1]


def chord(tri, u, v, pu, pv, du, dv):
    """The parameters a <= 0 <= b where the map line (pu, pv) + t (du, dv) meets the border
    of the triangulation (the edges of one unmasked triangle): the fault crossed end to end.
    Falls back on the nodes' extent along (du, dv) when the line meets no border edge."""
    triangles = tri.get_masked_triangles()  # the unmasked ones, despite the name
    edges = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]],
                                    triangles[:, [2, 0]]]), axis=1)
    unique, count = np.unique(edges, axis=0, return_counts=True)
    border = unique[count == 1]
    ax, ay = u[border[:, 0]], v[border[:, 0]]
    ex, ey = u[border[:, 1]] - ax, v[border[:, 1]] - ay
    denom = du * ey - dv * ex
    ok = np.abs(denom) > 1e-12 * np.hypot(ex, ey)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = ((ax - pu) * ey - (ay - pv) * ex) / denom
        s = ((ax - pu) * dv - (ay - pv) * du) / denom
    hit = ok & (s >= -1e-9) & (s <= 1 + 1e-9)
    size = max(np.ptp(u), np.ptp(v))
    if hit.any():
        a, b = min(t[hit].min(), 0.0), max(t[hit].max(), 0.0)
        if b - a > 1e-9 * size:
            return a, b
    along = (u - pu) * du + (v - pv) * dv
    return min(along.min(), 0.0), max(along.max(), 0.0)


class Segment:
    """A profile: kind 'strike' or 'dip' (the default pair) or None (-line), its ends p0, p1,
    the sample points and distances from p0, their map coordinates and the sampled values at
    each time."""

    def __init__(self, kind, p0, p1, samples, plane, maps):
        self.kind, self.p0, self.p1 = kind, p0, p1
        self.distance = np.linspace(0.0, np.linalg.norm(p1 - p0), samples)
        self.points = p0 + np.outer(self.distance / self.distance[-1], p1 - p0)
        self.u, self.v = plane.project(self.points)
        self.profiles = [m.sample(self.u, self.v) for m in maps]

    def axis(self):
        """The abscissa of the profile's plot and its label: the map coordinate along the
        segment for the default pair (as on the maps), the distance from p0 for -line."""
        if self.kind == "strike":
            return self.u, "along strike from the centroid [m]"
        if self.kind == "dip":
            return self.v, "up dip from the centroid [m] (shallower to the right)"
        return self.distance, "distance along the segment from its first point [m]"


class Fault3d:
    """Everything drawn for one 3D fault, computed (and checked) before any file is written."""

    def __init__(self, case, name, times, line, samples):
        self.case, self.name, self.times = case, name, times
        self.tables = [readTable3d(os.path.join(case, t, "fractures", name + ".dat"))
                       for t in times]
        self.plane = MapPlane(self.tables[-1])
        self.maps = [FaultMaps(table, self.plane) for table in self.tables]
        last = self.maps[-1]
        if last.foldWarning:
            print(f"plotFracture: warning: {last.foldWarning}", file=sys.stderr)
        if line is None:
            # Two profiles, along strike and along dip, through the node of largest slip at
            # the last time (where the fault slips: a profile through the centroid may miss a
            # slipping patch altogether), each across the whole fault; through the centroid
            # where nothing slips.
            slip = last.table["slipMagnitude"]
            k = int(np.argmax(slip))
            if slip[k] > 0:
                pu, pv = last.u[k], last.v[k]
                node = np.array([last.table[c][k] for c in "xyz"])
                self.through = f"through the largest slip, {slip[k]:.3g} m at {fmtPoint(node)}"
            else:
                pu = pv = 0.0
                self.through = "through the centroid (no slip)"
            self.segments = []
            for kind, du, dv in (("strike", 1.0, 0.0), ("dip", 0.0, 1.0)):
                a, b = chord(last.tri, last.u, last.v, pu, pv, du, dv)
                # The strike profile from left to right on the map, the dip one from the
                # deep end up (up dip to the right, like the map's vertical axis).
                ends = self.plane.point([pu + a * du, pu + b * du], [pv + a * dv, pv + b * dv])
                self.segments.append(Segment(kind, ends[0], ends[1], samples, self.plane,
                                             self.maps))
        else:
            self.through = None
            self.segments = [Segment(None, line[0], line[1], samples, self.plane, self.maps)]
            seg = self.segments[0]
            if not any(np.isfinite(p["slipMagnitude"]).any() for p in seg.profiles):
                raise PlotError(f"-line: the segment {fmtPoint(seg.p0)} -> {fmtPoint(seg.p1)} "
                                f"does not cross fracture '{name}' (projected on its map "
                                "plane)")
        self.law = fractureEntry(case, name, "law")
        self.mu = frictionCoefficient(case, name)

    def decorateMap(self, ax):
        """Equal scales, the axes along strike and up dip, and z on a right-hand axis (z of the
        map plane: exact on a flat fault) unless the fault is horizontal (z then constant: in
        the title)."""
        ax.set_aspect("equal")
        ax.set_xlabel("along strike from the centroid [m]")
        ax.set_ylabel("up dip from the centroid [m]")
        if self.plane.horizontal:
            ax.set_xlabel("x - x$_c$ [m] (along strike)")
            ax.set_ylabel("y - y$_c$ [m] (up dip)")
            return
        z = ax.secondary_yaxis("right", functions=(self.plane.zOf, self.plane.vOf))
        z.set_ylabel("z [m]" if self.plane.flat else "z of the map plane [m]")

    def drawMaps(self, out):
        m, t = self.maps[-1], self.times[-1]
        table = m.table
        # Room for the z axis right of each map, before its colorbar.
        self.pad = 0.05 if self.plane.horizontal else 0.17
        # Side by side for a roundish fault, stacked for an elongated one.
        aspect = np.ptp(m.u) / max(np.ptp(m.v), 1e-300)
        opening = "opening" in table  # a fourth map: the opening of fractures that open
        pressure = m.pressure  # two more: the fluid pressure p and sigma'_n = sigma_n + p
        if pressure:
            # Two rows of three maps (three rows of two for an elongated fault): slip, ST,
            # states; p, sigma'_n and the opening (or nothing).
            if aspect > 1.4:
                fig, grid = plt.subplots(3, 2, figsize=(14, min(24.0, 3 * 6 / aspect + 3.5)))
                axes = grid.T.ravel()
            else:
                fig, grid = plt.subplots(2, 3, figsize=(19, 11.5))
                axes = grid.ravel()
            axes = list(axes)
            axPressure, axEffective = axes[3], axes[4]
            axOpening = axes[5] if opening else None
            if not opening:
                axes[5].remove()
                axes = axes[:5]
        elif opening:
            fig, grid = plt.subplots(2, 2, figsize=(14, 11.5))
            axes = grid.ravel()
        elif aspect > 1.4:
            fig, axes = plt.subplots(3, 1, figsize=(10, min(18.0, 3 * 7.5 / aspect + 2.5)))
        else:
            fig, axes = plt.subplots(1, 3, figsize=(18, 5.8))
        axSlip, axST, axState = axes[:3]
        if opening:
            axOpen = axOpening if pressure else axes[3]
            pc = axOpen.tripcolor(m.tri, table["opening"], shading="gouraud", cmap="cividis")
            fig.colorbar(pc, ax=axOpen, shrink=0.85, pad=self.pad, label="opening g [m]")
            axOpen.set_title("opening g = $-[[u]] \\cdot n_\\Gamma$ (contact unilateral)",
                             fontsize=10)
        if pressure:
            self.drawPressureMaps(fig, m, axPressure, axEffective)
        pc = axSlip.tripcolor(m.tri, table["slipMagnitude"], shading="gouraud", cmap="viridis")
        fig.colorbar(pc, ax=axSlip, shrink=0.85, pad=self.pad, label="slip magnitude |slip| [m]")
        for seg in self.segments:  # under the arrows
            axSlip.plot(seg.u, seg.v, "--", color="firebrick", lw=1.2)
        magnitude = np.hypot(m.slipU, m.slipV)
        if magnitude.max() > 0:
            # At most about 400 arrows: on a grid over the map when there are more nodes.
            if len(m.u) <= 400:
                qu, qv, su, sv = m.u, m.v, m.slipU, m.slipV
            else:
                gu, gv = np.meshgrid(np.linspace(m.u.min(), m.u.max(), 20),
                                     np.linspace(m.v.min(), m.v.max(), 20))
                qu, qv = gu.ravel(), gv.ravel()
                su = np.ma.filled(mtri.LinearTriInterpolator(m.tri, m.slipU)(qu, qv), np.nan)
                sv = np.ma.filled(mtri.LinearTriInterpolator(m.tri, m.slipV)(qu, qv), np.nan)
                inside = np.isfinite(su) & np.isfinite(sv)
                qu, qv, su, sv = qu[inside], qv[inside], su[inside], sv[inside]
            # The longest arrow a tenth of the map's size (autoscaling on the mean length
            # stretches them across the map when only a small patch slips); none drawn for
            # zero slip.
            size = max(np.ptp(m.u), np.ptp(m.v))
            longest = np.nanmax(np.hypot(su, sv)) if len(su) else 0.0
            if longest > 0:
                axSlip.quiver(qu, qv, su, sv, color="white", edgecolor="black", linewidth=0.3,
                              width=0.004, pivot="mid", angles="xy", scale_units="xy",
                              scale=longest / (size / 10), minlength=0, zorder=3)
        if self.through is None:
            dashed = "the profile's segment (-line)"
        else:
            dashed = ("the profiles along strike and dip\nthrough the "
                      + ("largest slip" if self.through.startswith("through the largest")
                         else "centroid (no slip)"))
        axSlip.set_title("slip magnitude; arrows: the hanging wall's slip;\ndashed: " + dashed,
                         fontsize=10)
        if m.tractionTri is not None:
            pc = axST.tripcolor(m.tractionTri, table["ST"][m.keep], shading="gouraud",
                                cmap="magma")
            fig.colorbar(pc, ax=axST, shrink=0.85, pad=self.pad,
                         label=r"ST = $|\tau| / (-\sigma'_n)$")
            title = "slip tendency ST (non-tip nodes)"
            if self.law in COULOMB_LAWS and self.mu is not None:
                title += f"; $\\mu_f$ = {self.mu:g}"
            axST.set_title(title, fontsize=10)
        else:
            axST.set_title("slip tendency ST: fewer than 3 nodes with tractions", fontsize=10)
        axState.triplot(m.tri, color="0.8", lw=0.4)
        styles = {"tip": ("x", "black"), "stick": ("o", "tab:blue"), "slip": ("^", "tab:red"),
                  "open": ("s", "tab:green"), "junction": ("D", "tab:purple")}
        for state, (marker, color) in styles.items():
            sel = np.array([s == state for s in table["state"]])
            if sel.any():
                axState.scatter(m.u[sel], m.v[sel], marker=marker, s=14, color=color,
                                label=f"{state} ({sel.sum()})")
        # The legend above the map, as its title: right of it the z axis would hide it.
        axState.legend(fontsize=8, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=4,
                       title="node states", title_fontsize=10, frameon=False,
                       handletextpad=0.2, columnspacing=1.0)
        for ax in axes:
            self.decorateMap(ax)
        status = statusWord(table["status"])
        fig.suptitle(f"{os.path.basename(os.path.abspath(self.case))}: fault '{self.name}' at "
                     f"t = {t}" + (f" ({status})" if status and status != "converged" else "")
                     + (f", law {self.law}" if self.law else "")
                     + f"\nmap plane: {self.plane.describe()}", fontsize=10)
        fig.tight_layout()
        saveFigure(fig, out)
        plt.close(fig)

    def drawPressureMaps(self, fig, m, axPressure, axEffective):
        """The maps of the fluid pressure p and of sigma'_n = sigma_n + p, with the outline of
        the slipping nodes (where the fault slips against where the fluid has reached)."""
        table = m.table
        if m.pressureEverywhere:
            pc = axPressure.tripcolor(m.tri, table["pressure"], shading="gouraud",
                                      cmap="Blues")
        elif m.tractionTri is not None:
            pc = axPressure.tripcolor(m.tractionTri, table["pressure"][m.keep],
                                      shading="gouraud", cmap="Blues")
        else:
            pc = None
        if pc is not None:
            fig.colorbar(pc, ax=axPressure, shrink=0.85, pad=self.pad,
                         label="fluid pressure p [Pa]")
        if m.tractionTri is not None:
            pc = axEffective.tripcolor(m.tractionTri, table["sigmaNEffective"][m.keep],
                                       shading="gouraud", cmap="cividis")
            fig.colorbar(pc, ax=axEffective, shrink=0.85, pad=self.pad,
                         label=r"$\sigma'_n = \sigma_n + p$ [Pa] (compression < 0)")
        slipping = np.array([s == "slip" for s in table["state"]], dtype=float)
        outline = ""
        if slipping.any() and not slipping.all():
            for ax in (axPressure, axEffective):
                ax.tricontour(m.tri, slipping, levels=[0.5], colors="red", linewidths=1.2)
            outline = "\nred: the outline of the slipping nodes"
        axPressure.set_title(f"fluid pressure p{outline}", fontsize=10)
        axEffective.set_title(f"effective normal stress $\\sigma'_n$ (non-tip nodes){outline}",
                              fontsize=10)

    def drawProfile(self, out):
        """One column per segment (along strike, along dip; or the -line), one row per
        quantity, one curve per chosen time. Each panel has its own y range: a row shared
        between the columns would flatten the variation along strike under the trend down
        dip."""
        profiles = [p for seg in self.segments for p in seg.profiles]
        keys = (("slipMagnitude", "slip magnitude [m]"), ("sigmaN", r"$\sigma_n$ [Pa]"),
                ("tauMagnitude", r"$|\tau|$ [Pa]"), ("ST", r"ST = $|\tau| / (-\sigma'_n)$"))
        if all("opening" in p for p in profiles):
            keys += (("opening", "opening g [m]"),)
        if all("pressure" in p for p in profiles):
            keys += (("pressure", "fluid pressure p [Pa]"),
                     ("sigmaNEffective", r"$\sigma'_n = \sigma_n + p$ [Pa]"))
        columns = len(self.segments)
        fig, axes = plt.subplots(len(keys), columns, figsize=(8 if columns == 1 else 14,
                                                              2.5 * len(keys)),
                                 sharex="col", squeeze=False)
        colors = plt.cm.viridis([0.15 + 0.7 * i / max(1, len(self.times) - 1)
                                 for i in range(len(self.times))])
        caseName = os.path.basename(os.path.abspath(self.case))
        for column, seg in enumerate(self.segments):
            x, xlabel = seg.axis()
            for t, profile, table, color in zip(self.times, seg.profiles, self.tables, colors):
                word = statusWord(table["status"])
                label = f"t = {t}" + (f" ({word})" if word and word != "converged" else "")
                for row, (key, _) in enumerate(keys):
                    axes[row, column].plot(x, profile[key], ".-", color=color, ms=2, lw=1,
                                           label=label)
            if self.law in COULOMB_LAWS and self.mu is not None and self.mu > 0:
                axes[3, column].axhline(self.mu, color="firebrick", ls="--", lw=1.2,
                                        label=f"$\\mu_f$ = {self.mu:g}")
            for row, (_, ylabel) in enumerate(keys):
                ax = axes[row, column]
                if column == 0:
                    ax.set_ylabel(ylabel)
                ax.grid(True, alpha=0.3)
                ax.legend(fontsize=8)
            axes[-1, column].set_xlabel(xlabel)
            ends = f"{self.fmtPoint(seg.p0)} -> {self.fmtPoint(seg.p1)}"
            if seg.kind is None:
                title = (f"{caseName}: fault '{self.name}', profile {ends}\n(linear "
                         "interpolation on the triangulated fault; tractions on its non-tip "
                         "nodes)")
            elif seg.kind == "strike":
                title = f"along strike, left to right on the maps:\n{ends}"
            else:
                title = f"along dip, from the deep end up:\n{ends}"
            axes[0, column].set_title(title, fontsize=9)
            if seg.kind == "dip" and not self.plane.horizontal:
                # z at the top of the dip column (of the map plane: exact on a flat fault).
                z = axes[0, column].secondary_xaxis("top", functions=(self.plane.zOf,
                                                                      self.plane.vOf))
                z.set_xlabel("z [m]" if self.plane.flat else "z of the map plane [m]",
                             fontsize=9)
        if self.through is not None:
            fig.suptitle(f"{caseName}: fault '{self.name}', profiles {self.through}\n(linear "
                         "interpolation on the triangulated fault; tractions on its non-tip "
                         "nodes)", fontsize=10)
        fig.tight_layout()
        saveFigure(fig, out)
        plt.close(fig)

    def fmtPoint(self, p):
        """A point for titles and messages, round-off below 1e-9 of the fault's size as 0."""
        m = self.maps[-1]
        size = max(np.ptp(m.u), np.ptp(m.v))
        return fmtPoint(np.where(np.abs(p) < 1e-9 * size, 0.0, p))

    def profileCsv(self):
        """The samples: time,distance,x,y,z then the values (pressure,sigmaNEffective last
        where every table has them); the default pair adds a first column profile (strike or
        dip), -line keeps the columns without it."""
        profiles = [p for seg in self.segments for p in seg.profiles]
        keys = ("slipMagnitude", "sigmaN", "tauMagnitude", "ST")
        # A fluid pressure at every chosen time: its columns after the others.
        if all("pressure" in p for p in profiles):
            keys += ("pressure", "sigmaNEffective")
        named = self.segments[0].kind is not None
        lines = [("profile," if named else "") + "time,distance,x,y,z," + ",".join(keys)]
        for seg in self.segments:
            for t, profile in zip(self.times, seg.profiles):
                for i, d in enumerate(seg.distance):
                    values = [d, *seg.points[i]] + [profile[k][i] for k in keys]
                    lines.append(",".join(([seg.kind] if named else []) + [t]
                                          + [f"{v:.12g}" for v in values]))
        return "\n".join(lines) + "\n"


def fmtPoint(p):
    return "(" + " ".join(f"{c:g}" for c in p) + ")"


def main(argv):
    # OpenFOAM-style single-dash options: -help as well as -h.
    ap = argparse.ArgumentParser(
        prog="plotFracture", description=__doc__.split("\n")[0], add_help=False,
        epilog="2D tables: ST (or tractions) and slip along the arclength. 3D tables: maps of "
        "slip magnitude (arrows: slip), ST and node states over each fault, along strike "
        "and up dip, and profiles along strike and dip through the largest slip (or -line). "
        "Details: the header of this script and README.md (plotFracture).")
    ap.add_argument("-h", "-help", "--help", action="help", help="print this help and exit")
    ap.add_argument("-case", required=True, help="case folder")
    ap.add_argument("-fracture", help="fracture name (default: every fracture)")
    ap.add_argument("-times", help="comma-separated times (default: every time folder)")
    ap.add_argument("-o", dest="out", help="output PNG of the fracture figure")
    ap.add_argument("-convergence", help="output PNG of the convergence figure")
    ap.add_argument("-noConvergence", action="store_true", help="no convergence figure")
    ap.add_argument("-line", metavar="x0,y0,z0:x1,y1,z1",
                    help="3D: the profile's segment, two points [m] projected on the fault's "
                    "map plane (default: two, along strike and along dip through the node "
                    "of largest slip)")
    ap.add_argument("-profile", metavar="OUT.png",
                    help="3D: output PNG of the profile (default "
                    "postProcessing/fracture_<name>_profile.png)")
    ap.add_argument("-profileCsv", metavar="OUT.csv",
                    help="3D: also write the profile's samples as CSV ([profile,]time,"
                    "distance,x,y,z,slipMagnitude,sigmaN,tauMagnitude,ST[,pressure,"
                    "sigmaNEffective]; profile strike|dip without -line; nan off the fault)")
    ap.add_argument("-samples", metavar="N", help="3D: points along the profile (default 201)")
    # A value that starts with a minus sign (-line -250,-433,0:250,433,0) would be read as an
    # option: joined to its option as -line=VALUE, which argparse takes as it is.
    joined, i = [], 0
    while i < len(argv):
        if (argv[i] in ("-line", "-times", "-samples") and i + 1 < len(argv)
                and re.match(r"-[0-9.]", argv[i + 1])):
            joined.append(argv[i] + "=" + argv[i + 1])
            i += 2
        else:
            joined.append(argv[i])
            i += 1
    a = ap.parse_args(joined)

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

    # 3D faults: every table read and checked, the profile sampled, before any file is written.
    faults3d = {}
    for name in names:
        kinds = {is3dTable(os.path.join(case, t, "fractures", name + ".dat")) for t in times}
        if len(kinds) > 1:
            raise PlotError(f"{case}: fracture '{name}' has 2D and 3D tables (header '# s x y' "
                            "at some times, '# x y z' at others)")
        if kinds == {True}:
            faults3d[name] = None
    only3d = [opt for opt, value in (("-line", a.line), ("-profile", a.profile),
                                     ("-profileCsv", a.profileCsv), ("-samples", a.samples))
              if value is not None]
    for opt in only3d:
        flat = [n for n in names if n not in faults3d]
        if flat:
            raise PlotError(f"{opt}: fracture '{flat[0]}' has a 2D table (header '# s x y ...'); "
                            f"{opt} is for 3D fault surfaces")
        if len(names) > 1 and opt != "-samples":
            raise PlotError(f"{opt}: {len(names)} fractures ({' '.join(names)}); choose one "
                            "with -fracture")
    line = parseLine(a.line) if a.line is not None else None
    samples = 201
    if a.samples is not None:
        try:
            samples = int(a.samples)
        except ValueError:
            samples = 0
        if samples < 2:
            raise PlotError(f"-samples: expected a whole number >= 2, got '{a.samples}'")
    for name in faults3d:
        faults3d[name] = Fault3d(case, name, times, line, samples)

    post = os.path.join(case, "postProcessing")
    written = []
    for name in names:
        out = a.out or os.path.join(post, f"fracture_{name}.png")
        os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
        fault = faults3d.get(name)
        if fault is None:
            shows, opening, pressure = plotFracture(case, name, times, out)
            parts = [shows, "slip"] + (["opening"] if opening else []) + \
                (["pressure", "effective normal stress"] if pressure else [])
            written.append(f"{out} ({', '.join(parts[:-1])} and {parts[-1]})")
            continue
        fault.drawMaps(out)
        last = fault.maps[-1]
        parts = ["ST", "node states"] + (["opening"] if "opening" in last.table else []) + \
            (["pressure", "effective normal stress"] if last.pressure else [])
        what = ", ".join(parts[:-1]) + " and " + parts[-1]
        written.append(f"{out} (maps of slip magnitude, {what} at t = {times[-1]}; "
                       f"{fault.plane.axesText()})")
        profile = a.profile or os.path.join(post, f"fracture_{name}_profile.png")
        os.makedirs(os.path.dirname(os.path.abspath(profile)), exist_ok=True)
        fault.drawProfile(profile)
        if fault.through is None:
            seg = fault.segments[0]
            written.append(f"{profile} (profile {fmtPoint(seg.p0)} -> {fmtPoint(seg.p1)})")
        else:
            written.append(f"{profile} (profiles along strike and dip {fault.through}: "
                           + ", ".join(f"{seg.kind} {fault.fmtPoint(seg.p0)} -> "
                                       f"{fault.fmtPoint(seg.p1)}"
                                       for seg in fault.segments) + ")")
        if a.profileCsv:
            os.makedirs(os.path.dirname(os.path.abspath(a.profileCsv)), exist_ok=True)
            writeTextAtomically(a.profileCsv, fault.profileCsv())
            written.append(f"{a.profileCsv} (profile samples)")
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
