#!/usr/bin/env python3
"""Two runs of this case against each other: their earthquakes from global.dat (an event
starts where the fault's largest slip rate reaches 1e-3 m/s and ends below 1e-4 m/s).

    bp3Compare.py REFERENCE OTHER [--bound SECONDS]

prints one line per event (onset, the shift of OTHER's onset [s] and of its peak log10 slip
rate), then `events N M shift S peak P` (the largest shifts). With --bound it exits 1 where the
numbers of events differ, an onset moves by more than the bound or a peak by more than 0.01
(used by tests/regression/faultOperatorHierarchical.sh and
utilities/frictionStudy/faultOperatorStudy.sh).
"""
import argparse
import sys


def events(case):
    on, peaks, above = [], [], False
    for line in open(case + "/postProcessing/faultOutput/global.dat"):
        p = line.split()
        if not p or p[0].startswith("#") or p[0] == "t":
            continue
        t, lv = float(p[0]), float(p[1])
        if lv > -3 and not above:
            on.append(t); peaks.append(lv); above = True
        elif above:
            peaks[-1] = max(peaks[-1], lv)
        if lv < -4:
            above = False
    return on, peaks


ap = argparse.ArgumentParser()
ap.add_argument("reference")
ap.add_argument("other")
ap.add_argument("--bound", type=float)
a = ap.parse_args()
(ta, pa), (tb, pb) = events(a.reference), events(a.other)
for x, y, px, py in zip(ta, tb, pa, pb):
    print("onset %.3f yr: %+.3g s; peak log10 V %+.2e" % (x / 31536000.0, y - x, py - px))
shift = max([abs(x - y) for x, y in zip(ta, tb)] or [0])
peak = max([abs(x - y) for x, y in zip(pa, pb)] or [0])
print("events %d %d shift %.3g peak %.3g" % (len(ta), len(tb), shift, peak))
if a.bound is not None:
    if not ta:
        sys.exit("FAIL: the reference run has no event")
    if len(ta) != len(tb):
        sys.exit("FAIL: %d events against the reference's %d" % (len(tb), len(ta)))
    if shift > a.bound or peak > 0.01:
        sys.exit("FAIL: onset off by %.3g s (bound %g) or peak by %.3g" % (shift, a.bound, peak))
