#!/usr/bin/env python3
"""Pictures of a run of cases/seasBP5 (SEAS BP5-QD): one earthquake's rupture on the fault and
the cycles (README.md, "Benchmark: SEAS BP5-QD").

  ./bp5Plot.py [CASE] [--event K] [--output FILE]

reads postProcessing/faultOutput: rupture_K.dat (default: the event that most nodes reached,
the first of them on a tie), global.dat and fltst_strk+00dp+10.dat, and draws
  (a) the event's slip along strike on the fault plane (filled) and its rupture front, the
      contours of the rupture time every few seconds, with the velocity-weakening patch and
      the nucleation zone outlined;
  (b) the largest slip rate on the fault against time;
  (c) the slip along strike at the station strk+00dp+10 (x = 0, 10 km deep) against time.
Default output: postProcessing/bp5-rupture.png. Needs python3-matplotlib (Debian).
"""
import argparse
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402

YEAR = 365 * 86400.0


def rows(path):
    out = []
    for line in open(path):
        if line[:1] in "#xt" or not line.strip():
            continue
        out.append([float(v) for v in line.split()])
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("case", nargs="?", default=".")
    p.add_argument("--event", type=int, default=0, help="the event k of rupture_k.dat (default: the largest)")
    p.add_argument("--output", default="", help="the picture (default postProcessing/bp5-rupture.png)")
    a = p.parse_args()
    out = os.path.join(a.case, "postProcessing", "faultOutput")
    if not os.path.isdir(out):
        sys.exit(f"bp5Plot.py: no folder {out}: run the case first")
    files = sorted((int(m.group(1)), f) for f in os.listdir(out)
                   for m in [re.fullmatch(r"rupture_(\d+)\.dat", f)] if m)
    if not files:
        sys.exit(f"bp5Plot.py: no rupture_<k>.dat in {out}: faultOutput needs 'ruptures yes;' and "
                 "an event that ended")
    events = {}
    for k, f in files:
        text = open(os.path.join(out, f)).read()
        m = re.search(r"onset (\S+) s, end (\S+) s, peak slip rate (\S+) m/s; (\d+) of", text)
        if not m:
            sys.exit(f"bp5Plot.py: {f}: not a rupture file of frictionSolver (no header)")
        events[k] = (float(m.group(1)), float(m.group(2)), float(m.group(3)), int(m.group(4)), f)
    if a.event:
        if a.event not in events:
            sys.exit(f"bp5Plot.py: no rupture_{a.event}.dat; events: {sorted(events)}")
        k = a.event
    else:
        k = max(sorted(events), key=lambda j: events[j][3])
    onset, end, peak, nodes, name = events[k]
    r = rows(os.path.join(out, name))
    if any(len(x) != 6 for x in r):
        sys.exit(f"bp5Plot.py: {name}: expected the 3D columns x y z rupture_time slip_2 slip_3")
    x = [v[0] / 1e3 for v in r]
    depth = [-v[2] / 1e3 for v in r]
    slip = [v[4] for v in r]
    tri = mtri.Triangulation(x, depth)
    fig = plt.figure(figsize=(11, 8.5))
    ax = fig.add_subplot(2, 1, 1)
    filled = ax.tricontourf(tri, slip, levels=20, cmap="viridis")
    fig.colorbar(filled, ax=ax, label="slip along strike over the event [m]", shrink=0.9)
    times = [v[3] for v in r]
    hit = [t for t in times if not math.isnan(t)]
    if len(hit) >= 3 and max(hit) > 0:
        step = max(1.0, round(max(hit) / 24))
        # Only the triangles whose three nodes the rupture reached carry its front.
        mask = [any(math.isnan(times[i]) for i in t) for t in tri.triangles]
        if not all(mask):
            reached = mtri.Triangulation(x, depth, tri.triangles, mask=mask)
            front = ax.tricontour(reached, [0.0 if math.isnan(t) else t for t in times],
                                  levels=[step * i for i in range(1, int(max(hit) / step) + 1)],
                                  colors="white", linewidths=0.8)
            ax.clabel(front, fmt="%g s", fontsize=7)
    for (x0, x1, z0, z1), style, label in (((-30, 30, 4, 16), "--", "velocity weakening"),
                                           ((-30, -18, 4, 16), ":", "nucleation zone")):
        ax.plot([x0, x1, x1, x0, x0], [z0, z0, z1, z1, z0], "r" + style, lw=1.2, label=label)
    ax.set_xlim(min(x), max(x))
    ax.set_ylim(max(depth), 0)
    ax.set_aspect("equal")
    ax.set_xlabel("along strike x [km]")
    ax.set_ylabel("depth [km]")
    ax.legend(loc="lower right", fontsize=8)
    ax.set_title(f"(a) event {k}: onset {onset / YEAR:.2f} yr, {end - onset:.0f} s long, peak "
                 f"slip rate {peak:.2f} m/s; white: the rupture front (rupture time)", fontsize=10)
    g = rows(os.path.join(out, "global.dat"))
    ax = fig.add_subplot(2, 2, 3)
    ax.plot([v[0] / YEAR for v in g], [v[1] for v in g], lw=0.8)
    ax.axhline(math.log10(1e-3), color="grey", lw=0.6, ls="--")
    ax.set_xlabel("time [yr]")
    ax.set_ylabel("log10 max slip rate [m/s]")
    ax.set_title("(b) the largest slip rate on the fault", fontsize=10)
    station = os.path.join(out, "fltst_strk+00dp+10.dat")
    ax = fig.add_subplot(2, 2, 4)
    if os.path.exists(station):
        s = rows(station)
        ax.plot([v[0] / YEAR for v in s], [v[1] for v in s], lw=0.8)
    ax.set_xlabel("time [yr]")
    ax.set_ylabel("slip_2 [m]")
    ax.set_title("(c) slip along strike at strk+00dp+10", fontsize=10)
    fig.tight_layout()
    path = a.output or os.path.join(a.case, "postProcessing", "bp5-rupture.png")
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, path)
    print(f"bp5Plot.py: wrote {path} (event {k} of {len(events)}: {nodes} nodes ruptured)")


if __name__ == "__main__":
    main()
