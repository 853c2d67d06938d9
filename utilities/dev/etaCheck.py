#!/usr/bin/env python3
"""How good is frictionSolver's time-left estimate? Reads a log (or runs a case and reads its
log) and compares, at each step, the '~E s left' of the step line with the wall time the
remaining steps actually took: the last step's loop time minus this step's, both from the
'[step k/n, X s' of the lines (the same clock as the estimate, so nothing is timed here).
Prints one row per step with the ratio estimate/actual, and the estimate of the old rule
(the mean of all steps so far: X/done x left) beside it, then the worst ratio either way from
step 2 on. Exit status 1 when that is 2 or more (README.md, "frictionSolver").

  utilities/dev/etaCheck.py --log cases/strikeSlipFault/log.frictionSolver
  utilities/dev/etaCheck.py --case /tmp/ssf [--bin build/bin]   # runs frictionSolver -overwrite
"""
import argparse
import os
import re
import subprocess
import sys

STEP = re.compile(r"^Time = \S+ .*\[step (\d+)/(\d+), (\S+) s(?:, ~(\S+) s left)?\]")


def rows(text):
    out = []
    for line in text.splitlines():
        m = STEP.match(line)
        if m:
            k, n, x, e = m.groups()
            out.append((int(k), int(n), float(x), float(e) if e is not None else None))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--log", help="a frictionSolver log to read")
    ap.add_argument("--case", help="a split case folder to run (frictionSolver -overwrite)")
    ap.add_argument("--bin", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "build", "bin"))
    a = ap.parse_args()
    if bool(a.log) == bool(a.case):
        ap.error("give one of --log and --case")
    if a.case:
        log = os.path.join(a.case, "log.frictionSolver")
        with open(log, "w") as f:
            rc = subprocess.call([os.path.join(a.bin, "frictionSolver"), "-case", a.case, "-overwrite"],
                                 stdout=f, stderr=subprocess.STDOUT)
        if rc not in (0, 3):
            sys.exit(f"etaCheck: frictionSolver failed (exit {rc}); see {log}")
    else:
        log = a.log
    r = rows(open(log).read())
    if len(r) < 3:
        sys.exit(f"etaCheck: {log}: fewer than 3 step lines; the check needs a case with several steps")
    first = r[0][0]
    last_x = r[-1][2]
    worst = 1.0
    print(f"{'step':>6} {'loop s':>8} {'estimate s':>11} {'actual s':>9} {'ratio':>6} {'old rule s':>11} {'old ratio':>9}")
    for k, n, x, e in r:
        actual = last_x - x
        done = k - first + 1
        old = x / done * (n - k)
        ratio = e / actual if e is not None and actual > 0 else float("nan")
        old_ratio = old / actual if actual > 0 else float("nan")
        if e is not None and actual > 0 and done >= 2:
            worst = max(worst, ratio, 1 / ratio if ratio > 0 else float("inf"))
        es = f"{e:.3g}" if e is not None else "-"
        print(f"{k:>4}/{n:<2} {x:>8.3g} {es:>11} {actual:>9.3g} {ratio:>6.2f} {old:>11.3g} {old_ratio:>9.2f}")
    print(f"worst ratio from step 2 on (either way): {worst:.2f}")
    sys.exit(0 if worst < 2 else 1)


if __name__ == "__main__":
    main()
