#!/usr/bin/python3
"""Picture of a BP3-QD run's cycles: the cumulative slip along the fault every 5 years
between events (blue) and every second during them (red), against down-dip distance; and
the largest slip rate on the fault against time (postProcessing/faultOutput/slip.dat).

Usage: bp3Plot.py [CASE_DIR] [OUTPUT.png]   (default: postProcessing/bp3-cycles.png)
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

case = sys.argv[1] if len(sys.argv) > 1 else "."
out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(case, "postProcessing", "bp3-cycles.png")
YEAR = 365 * 86400.0
rows = []
with open(os.path.join(case, "postProcessing", "faultOutput", "slip.dat")) as f:
    for line in f:
        if line.startswith("#") or not line.strip():
            continue
        rows.append([float(x) for x in line.split()])
xd = [x / 1000 for x in rows[0][2:]]
data = rows[1:]
if not data:
    sys.exit("bp3Plot.py: no profile rows")
fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5), gridspec_kw={"width_ratios": [1, 1.4]})
lastBlue = None
for r in data:
    seismic = r[1] >= -3
    if seismic:
        left.plot(r[2:], xd, color="tab:red", lw=0.4)
    elif lastBlue is None or r[0] - lastBlue >= 5 * YEAR * 0.999:
        left.plot(r[2:], xd, color="tab:blue", lw=0.4)
        lastBlue = r[0]
left.invert_yaxis()
left.set_xlabel("cumulative slip [m]")
left.set_ylabel("down-dip distance [km]")
left.set_title("slip every 5 yr (blue), every 1 s while max V >= 1e-3 m/s (red)", fontsize=8)
right.plot([r[0] / YEAR for r in data], [r[1] for r in data], color="k", lw=0.7)
right.axhline(-3, color="tab:red", lw=0.5, ls="--")
right.set_xlabel("time [years]")
right.set_ylabel("log10 max slip rate [m/s]")
right.set_title("largest slip rate on the fault", fontsize=8)
fig.suptitle("SEAS BP3-QD", fontsize=9)
fig.tight_layout()
fig.savefig(out, dpi=110)
print("bp3Plot.py: wrote " + out)
