#!/usr/bin/env python3
"""cases/seasBP3/bp3Check.py --check on synthetic station files (seconds, no solver run).

A case whose station at 7.5 km has FDRA's own events for 60-degree thrust (each event: the
slip rate at its peak for one sample, the slip jumping by FDRA's slip), with surface station
files present, must pass; moving the third event by 4 years (an interval beyond the 3-year
bound) or halving an event's slip (beyond 10 %) must fail and name what. The surface stations
matter: their part of the report runs before the check and must not change what it compares
(it once replaced the events' reference by the offsets', and every case failed).
Usage: seasBP3Check.py SOURCE_DIR WORK_DIR
"""
import importlib.util
import os
import shutil
import subprocess
import sys

src, work = sys.argv[1], sys.argv[2]
script = os.path.join(src, "cases", "seasBP3", "bp3Check.py")
spec = importlib.util.spec_from_file_location("bp3Check", script)
bp3 = importlib.util.module_from_spec(spec)
spec.loader.exec_module(bp3)
reference = bp3.FDRA[("thrust", 60)]
assert len(reference) >= 4, "FDRA's thrust events"


def make(name, shift=0.0, slipFactor=1.0):
    case = os.path.join(work, name)
    shutil.rmtree(case, ignore_errors=True)
    out = os.path.join(case, "postProcessing", "faultOutput")
    os.makedirs(out)
    os.makedirs(os.path.join(case, "constant"))
    with open(os.path.join(case, "constant", "fractureProperties"), "w") as f:
        f.write("// written by bp3Case.py --dip 60 --sense thrust\n")
    rows, s = [], 0.0
    for k, (t, slip, peak) in enumerate(reference):
        t += shift * bp3.YEAR if k == 2 else 0.0
        slip *= slipFactor if k == 1 else 1.0
        rows += [(t - 1e6, s, -9.0), (t, s, __import__("math").log10(peak)), (t + 1e6, s + slip, -9.0)]
        s += slip
    with open(os.path.join(out, "fltst_dp075.dat"), "w") as f:
        f.write("# synthetic\nt slip slip_rate shear_stress normal_stress state\n")
        for t, sl, lv in rows:
            f.write("%21.13E %14.6E %14.6E %14.6E %14.6E %14.6E\n" % (t, sl, lv, 26.5, 50.0, 3.9))
    for station in ("srfst_fn+00", "srfst_fn-16", "srfst_fn+16"):
        with open(os.path.join(out, station + ".dat"), "w") as f:
            f.write("t disp1 disp2 vel1 vel2\n")
            for t, sl, lv in rows:
                v = 1e-3 if lv > -3 else 1e-10
                f.write("%21.13E %14.6E %14.6E %14.6E %14.6E\n" % (t, 0.1 * sl, 0.2 * sl, v, v))
    return case


def check(case):
    r = subprocess.run([sys.executable, "-B", script, case, "--check"], capture_output=True, text=True)
    return r.returncode, r.stdout + r.stderr


fails = []
rc, text = check(make("same"))
if rc != 0:
    fails.append("FDRA's own events failed the check:\n" + text)
rc, text = check(make("late", shift=4.0))
if rc != 1 or "interval" not in text:
    fails.append("an interval 4 years off passed (exit %d):\n%s" % (rc, text))
rc, text = check(make("small", slipFactor=0.5))
if rc != 1 or "slip" not in text:
    fails.append("half an event's slip passed (exit %d):\n%s" % (rc, text))
if fails:
    sys.exit("FAIL: " + "\nFAIL: ".join(fails))
print("PASS: bp3Check.py --check passes FDRA's events, fails a 4-year interval and half a slip")
