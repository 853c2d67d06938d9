#!/usr/bin/python3
"""Draws what frictionSolve.edp wrote to postProcessing/: the split mesh moved by 10 times
the displacement the plug-in returned, coloured by u_x (discontinuous across the fracture
where it slips),
and the fracture table's slip and slip tendency along the fracture, with the states.

Usage (from the case folder, after frictionSolve.edp; ./Allrun does this):
    /usr/bin/python3 plotResults.py [-o postProcessing/freefemResults.png]
Needs python3-matplotlib (Debian).
"""
import argparse
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

STATES = ["stick", "slip", "open", "tip", "junction"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-o", default="postProcessing/freefemResults.png", help="output PNG")
    ap.add_argument("--scale", type=float, default=10.0, help="displacement magnification")
    a = ap.parse_args()
    try:
        xyu = np.loadtxt("postProcessing/freefemDisplacement.dat", ndmin=2)
        tri = np.loadtxt("postProcessing/freefemTriangles.dat", ndmin=2, dtype=int)
        table = np.loadtxt("postProcessing/freefemTable.dat", ndmin=2)
    except OSError as e:
        sys.exit("plotResults.py: %s (run frictionSolve.edp first: ./Allrun)" % e)
    if xyu.shape[1] != 4 or tri.shape[1] != 4 or table.shape[1] < 10 or len(table) == 0:
        sys.exit("plotResults.py: postProcessing/freefem*.dat are not what frictionSolve.edp "
                 "writes (4 columns, 4 columns, at least 10 columns and a row)")

    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.6),
                                      gridspec_kw={"width_ratios": [1, 1.25]})
    x = xyu[:, 0] + a.scale * xyu[:, 2]
    y = xyu[:, 1] + a.scale * xyu[:, 3]
    # u_x: the fracture's faces carry different values where it slips (the jump is the slip)
    tp = left.tripcolor(x, y, tri[:, :3], xyu[:, 2] * 1e3, shading="gouraud", cmap="coolwarm")
    left.triplot(x, y, tri[:, :3], lw=0.15, color="k", alpha=0.4)
    left.set_aspect("equal")
    left.set_title("split mesh moved by %g u (FreeFEM fespace)" % a.scale, fontsize=10)
    left.set_xlabel("x [m]")
    left.set_ylabel("y [m]")
    fig.colorbar(tp, ax=left, shrink=0.8, label="u_x [mm]")

    s, slip, st, state = table[:, 1], table[:, 3], table[:, 7], table[:, -1].astype(int)
    right.plot(s, slip * 1e3, "-", color="C0", label="slip [mm]")
    for k, name in enumerate(STATES):
        on = state == k
        if on.any():
            right.plot(s[on], slip[on] * 1e3, "o", ms=3.5, color="C%d" % (k + 2), label=name)
    right.set_xlabel("x on the fracture [m]")
    right.set_ylabel("slip [mm]")
    other = right.twinx()
    other.plot(s, st, "--", color="C1", label="slip tendency |τ|/−σ_n")
    other.set_ylabel("slip tendency [-]")
    lines = right.get_legend_handles_labels()
    more = other.get_legend_handles_labels()
    right.legend(lines[0] + more[0], lines[1] + more[1], fontsize=8, loc="center right")
    right.set_title("the fracture table frictionSolve returned", fontsize=10)
    fig.tight_layout()
    os.makedirs(os.path.dirname(a.o) or ".", exist_ok=True)
    fig.savefig(a.o, dpi=110)
    print("wrote %s" % a.o)


if __name__ == "__main__":
    main()
