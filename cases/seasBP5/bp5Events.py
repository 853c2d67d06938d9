#!/usr/bin/python3
"""The events of a BP5-QD run (cases/seasBP5): from postProcessing/faultOutput/global.dat, each
time the largest slip rate on the fault reaches 1e-3 m/s (the benchmark's seismic threshold)
after being below it: its onset [years of 365 days], the interval since the previous one, the
peak slip rate [m/s] and the largest moment rate [N m/s]; and the slip along strike across it at
the station strk+00dp+10 (the centre of the velocity-weakening patch, 10 km deep).

Usage: bp5Events.py CASE_DIR
"""
import math
import os
import sys

case = sys.argv[1] if len(sys.argv) > 1 else "."
out = os.path.join(case, "postProcessing", "faultOutput")
year = 365 * 24 * 3600.0


def rows(path):
    with open(path) as f:
        return [[float(v) for v in line.split()] for line in f
                if line.strip() and line[0] not in "#t"]


g = rows(os.path.join(out, "global.dat"))
events, on = [], False
for t, logV, moment in g:
    if logV >= -3 and not on:
        events.append({"t0": t, "peak": logV, "moment": moment})
        on = True
    elif on and logV >= -3:
        events[-1]["peak"] = max(events[-1]["peak"], logV)
        events[-1]["moment"] = max(events[-1]["moment"], moment)
    elif on:
        events[-1]["t1"] = t
        on = False
st = rows(os.path.join(out, "fltst_strk+00dp+10.dat"))


def slipAt(t):
    """slip_2 at the station at the last row at or before t."""
    s = st[0][1]
    for r in st:
        if r[0] > t:
            break
        s = r[1]
    return s


print("event  onset [yr]  interval [yr]  peak V [m/s]  max moment rate [N m/s]  "
      "slip_2 at strk+00dp+10 [m]")
prev = None
for k, e in enumerate(events, 1):
    t1 = e.get("t1", g[-1][0])
    slip = slipAt(t1) - slipAt(e["t0"])
    print("%5d  %10.2f  %13s  %12.3f  %23.4g  %10.3f"
          % (k, e["t0"] / year, "-" if prev is None else "%.2f" % ((e["t0"] - prev) / year),
             10 ** e["peak"], e["moment"], slip))
    prev = e["t0"]
if not events:
    print("no event (max slip rate below 1e-3 m/s throughout)")
