#!/usr/bin/python3
"""plotNetwork.py: a map of a solved 2D case with several fractures.

The split mesh's regions (constant/splitMesh: points, triangles, regions; their names from
the gmsh mesh's $PhysicalNames where it has them), every fracture of the last
(or a given) time coloured by the magnitude of its slip, junction nodes (state `junction`,
and nodes shared by two fractures' tables) as circles and tips as dots.

Usage: plotNetwork.py [-case DIR] [-time T] [-o out.png]
  -case  the case folder (default: this script's folder)
  -time  the time folder (default: the latest)
  -o     output (default: <case>/postProcessing/network.png)
Errors (no split mesh, no time folder, unreadable table) go to stderr, exit 1.
"""
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402


def fail(message):
    print("plotNetwork.py: " + message, file=sys.stderr)
    sys.exit(1)


def readList(text, key, width):
    """The list after `key N (` in an OpenFOAM-syntax dictionary, as rows of `width` numbers."""
    m = re.search(r"(?m)^" + key + r"\s+(\d+)\s*\(", text)
    if not m:
        fail(f"no '{key}' list in the split mesh")
    n = int(m.group(1))
    numbers = re.findall(r"-?[0-9.]+(?:e[-+]?\d+)?", text[m.end():m.end() + 200 * n + 100])
    values = [float(v) for v in numbers[:n * width]]
    if len(values) < n * width:
        fail(f"the split mesh's '{key}' list is short")
    return [values[i * width:(i + 1) * width] for i in range(n)]


def regionNames(case):
    """Region number -> name from the gmsh mesh's $PhysicalNames (system/meshDict's `mesh`);
    empty for other formats."""
    names = {}
    meshDict = os.path.join(case, "system", "meshDict")
    try:
        mesh = re.search(r'mesh\s+"([^"]+)"', open(meshDict).read()).group(1)
        text = open(os.path.join(case, mesh)).read()
        block = re.search(r"\$PhysicalNames\s+\d+\s+(.*?)\$EndPhysicalNames", text, re.S)
        for dim, tag, name in re.findall(r'(\d+)\s+(\d+)\s+"([^"]*)"', block.group(1)):
            if dim == "2":
                names[int(tag)] = name
    except (OSError, AttributeError):
        pass
    return names


def readTable(path):
    rows = []
    with open(path) as f:
        header = f.readline().split()[1:]
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            items = line.split()
            rows.append(dict(zip(header, items)))
    if not rows:
        fail(f"{path}: no rows")
    return rows


def main(argv):
    case = os.path.dirname(os.path.abspath(__file__))
    time = None
    out = None
    i = 0
    while i < len(argv):
        if argv[i] in ("-case", "-time", "-o") and i + 1 < len(argv):
            if argv[i] == "-case":
                case = argv[i + 1]
            elif argv[i] == "-time":
                time = argv[i + 1]
            else:
                out = argv[i + 1]
            i += 2
        else:
            fail(f"unknown argument '{argv[i]}' (usage: plotNetwork.py [-case DIR] "
                 "[-time T] [-o out.png])")
    split = os.path.join(case, "constant", "splitMesh")
    if not os.path.isfile(split):
        fail(f"{split}: not found (run splitFractureNodes first)")
    text = open(split).read()
    points = readList(text, "points", 2)
    triangles = [[int(v) for v in t] for t in readList(text, "triangles", 3)]
    regions = [int(r[0]) for r in readList(text, "regions", 1)]

    times = [d for d in os.listdir(case)
             if re.fullmatch(r"[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?", d) and d != "0"
             and os.path.isdir(os.path.join(case, d, "fractures"))]
    if not times:
        fail(f"{case}: no time folder with fracture tables (run frictionSolver first)")
    time = time or max(times, key=float)
    folder = os.path.join(case, time, "fractures")
    if not os.path.isdir(folder):
        fail(f"{folder}: not found")
    tables = {f[:-4]: readTable(os.path.join(folder, f))
              for f in sorted(os.listdir(folder)) if f.endswith(".dat")}

    fig, ax = plt.subplots(figsize=(9, 6.2))
    x = [p[0] for p in points]
    y = [p[1] for p in points]
    names = regionNames(case)
    distinct = sorted(set(regions))
    shades = plt.get_cmap("Pastel2")
    colour = [distinct.index(r) for r in regions]
    ax.tripcolor(x, y, triangles, facecolors=colour, cmap=shades, vmin=0, vmax=7,
                 edgecolors="none")
    for k, r in enumerate(distinct):
        ax.fill([], [], color=shades(k / 7), label=names.get(r, f"region {r}"))

    slips = [abs(float(row["slip"])) for rows in tables.values() for row in rows]
    top = max(max(slips), 1e-300)
    norm = plt.Normalize(0, top)
    seen = {}
    for name, rows in tables.items():
        xy = [(float(r["x"]), float(r["y"])) for r in rows]
        s = [abs(float(r["slip"])) for r in rows]
        segments = [[xy[i], xy[i + 1]] for i in range(len(xy) - 1)]
        lines = LineCollection(segments, cmap="inferno_r", norm=norm, linewidths=4)
        lines.set_array([(s[i] + s[i + 1]) / 2 for i in range(len(s) - 1)])
        ax.add_collection(lines)
        at = xy[len(xy) // 5]
        ax.annotate(name, at, xytext=(8, -4), textcoords="offset points", fontsize=9)
        for r, p in zip(rows, xy):
            key = (round(p[0], 6), round(p[1], 6))
            seen.setdefault(key, set()).add(name)
            if r["state"] == "tip":
                ax.plot(*p, "k.", markersize=6)
    junctions = [k for k, v in seen.items() if len(v) > 1]
    for name, rows in tables.items():
        for r in rows:
            if r["state"] == "junction":
                junctions.append((float(r["x"]), float(r["y"])))
    if junctions:
        ax.plot([p[0] for p in junctions], [p[1] for p in junctions], "o", markersize=9,
                markerfacecolor="none", markeredgecolor="tab:blue", markeredgewidth=2,
                label="junction")
    fig.colorbar(lines, ax=ax, label="|slip| [m] at t = " + time, shrink=0.8)
    # The fractures with 500 m around them (within the mesh).
    fx = [float(r["x"]) for rows in tables.values() for r in rows]
    fy = [float(r["y"]) for rows in tables.values() for r in rows]
    ax.set_xlim(max(min(x), min(fx) - 500), min(max(x), max(fx) + 500))
    ax.set_ylim(max(min(y), min(fy) - 500), min(max(y), max(fy) + 500))
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(os.path.basename(os.path.abspath(case)) + ": fractures and layers, t = " + time)
    ax.legend(loc="upper left", fontsize=8, framealpha=0.9)
    out = out or os.path.join(case, "postProcessing", "network.png")
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    fig.savefig(out + ".partial.png", dpi=110, bbox_inches="tight")
    os.replace(out + ".partial.png", out)
    print("Wrote " + out)


if __name__ == "__main__":
    main(sys.argv[1:])
