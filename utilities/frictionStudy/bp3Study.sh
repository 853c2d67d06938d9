#!/usr/bin/env bash
# The accuracy/time study of the earthquake cycle (issue #30): cases/seasBP3's 60-degree
# thrust case for YEARS years (default 1500) at each fault cell size and Runge-Kutta tolerance
# of RUNS ("h:tolerance[:P2]", default 200:1e-6 200:1e-8 200:1e-10 100:1e-8 50:1e-8 25:1e-8),
# one after the other; per run the events at 7.5 km against FDRA's published data
# (cases/seasBP3/bp3Check.py): the first onset's error, the largest error of the next three
# intervals, the largest slip error of the first four events, and the cost (wall time, the
# Runge-Kutta steps and right-hand sides, the time per right-hand side, S_tt's size).
# With SUMMARY_ONLY=1 it only prints the table of the runs already in WORK_DIR.
# Usage: [RUNS="..."] [YEARS=N] bp3Study.sh [BIN_DIR] [WORK_DIR]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=$(cd "${1:-$root/build/bin}" && pwd)
work=${2:-$root/build/bp3Study}
runs=${RUNS:-"200:1e-6 200:1e-8 200:1e-10 100:1e-8 50:1e-8 25:1e-8"}
years=${YEARS:-1500}
mkdir -p "$work"
work=$(cd "$work" && pwd)
if [[ ${SUMMARY_ONLY:-0} != 1 ]]; then
  for r in $runs; do
    IFS=: read -r h tol order <<<"$r"
    d=$work/h${h}_tol${tol}${order:+_$order}
    rm -rf "$d"
    cp -r "$root/cases/seasBP3" "$d"
    (
      cd "$d"
      ./Allclean >/dev/null
      /usr/bin/python3 bp3Case.py --years "$years" --tolerance "$tol" >/dev/null
      [[ ${order:-} == P2 ]] && sed -i 's/^elementOrder    1;/elementOrder    2;/' system/frictionSolution
      ./Allmesh -h "$h" >/dev/null
      "$bin/splitFractureNodes" -case . >log.splitFractureNodes 2>&1
      start=$(date +%s.%N)
      "$bin/frictionSolver" -case . >log.frictionSolver 2>&1
      echo "$(date +%s.%N) - $start" | bc >wallTime
    )
  done
fi
/usr/bin/python3 - "$work" "$root/cases/seasBP3" <<'PY'
import glob, os, re, subprocess, sys
work, case = sys.argv[1], sys.argv[2]
YEAR = 365 * 86400.0
sys.path.insert(0, case)
print("| h [m] | elements | tolerance | events | first onset − FDRA [yr] | next 3 intervals − FDRA, largest [yr] | slip of events 1–4 − FDRA, largest | wall time | RK steps (rejected) | right-hand sides | per RHS | S_tt |")
print("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
def key(d):
    m = re.match(r"h([0-9.]+)_tol([0-9.e+-]+)", os.path.basename(d))
    return (-float(m.group(1)), -float(m.group(2))) if m else (0, 0)
for d in sorted(glob.glob(work + "/h*_tol*"), key=key):
    m = re.match(r"h([0-9.]+)_tol([0-9.e+-]+)(_P2)?", os.path.basename(d))
    if not m or not os.path.exists(d + "/wallTime"):
        continue
    out = subprocess.run(["/usr/bin/python3", case + "/bp3Check.py", d], capture_output=True, text=True).stdout
    ours, ref = [], []
    for line in out.splitlines():
        p = line.split()
        if not p or line.startswith("#") or not p[0].isdigit() or len(p) < 9:
            continue
        if p[1] != "-":
            ours.append((float(p[1]), float(p[3])))
        if p[5] != "-":
            ref.append((float(p[5]), float(p[7])))
    log = open(d + "/log.frictionSolver").read()
    w = re.search(r"Time integration: (\d+) Runge-Kutta steps accepted, (\d+) rejected, (\d+) right-hand sides in ([0-9.e+-]+) s \(([0-9.e+-]+) us each, fault outputs included; S_tt (\d+) x", log)
    wall = float(open(d + "/wallTime").read())
    first = ours[0][0] - ref[0][0] if ours else float("nan")
    gaps = [abs((ours[k][0] - ours[k - 1][0]) - (ref[k][0] - ref[k - 1][0])) for k in (1, 2, 3) if k < len(ours)]
    slips = [abs(ours[k][1] / ref[k][1] - 1) for k in range(min(4, len(ours)))]
    cost = ("%s (%s) | %s | %.0f us | %s" % (w.group(1), w.group(2), w.group(3), float(w.group(5)), w.group(6))
            if w else "– | – | – | –")
    print("| %s | %s | %s | %d | %+.2f | %s | %s | %.0f s | %s |" % (
        m.group(1), "P2" if m.group(3) else "P1", m.group(2), len(ours), first,
        "%.2f" % max(gaps) if gaps else "-", "%.1f %%" % (100 * max(slips)) if slips else "-",
        wall, cost))
PY
