#!/usr/bin/env bash
# What accuracy costs for slip-weakening friction near a loss of equilibrium:
# cases/slipWeakeningInjection (Garagash & Germanovich 2012: the slipping zone grows behind the
# pressure front until the quasi-static branch folds at X = sqrt(4 alpha t)/a_w = 4.914, where
# the solver reports 'nucleation'). Varied: the fault mesh size h (0.1, 0.05, 0.025 m; a_w = 1 m)
# at a time step of 0.05 s near the fold, and, at h = 0.05 m, the time step near the fold
# (0.1, 0.05, 0.025 s). The times are every 0.25 s up to 5.5 s, then every dt up to 6.5 s (the
# run stops at the nucleation). Prints per run: h, dt, the steps run, the wall time of
# frictionSolver [s] and its ratio to the h = 0.05 m, dt = 0.05 s run's (all measured in this
# run of the script, one after the other), the fold's X extrapolated from the patch stiffness
# (gg12Check.py: k^2 of the last two converged steps to 0) and its error against 4.914, the
# largest |a_h - a_ref|/a_w over the converged steps on the lower branch (X <= 4.914), and the
# last converged time and the nucleation's time, which bracket the fold (t = 6.04 s).
# Usage: slipWeakeningStudy.sh [BIN_DIR] [WORK_DIR]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-$root/build/bin}
work=${2:-$root/build/slipWeakeningStudy}
mkdir -p "$work"
work=$(cd "$work" && pwd)
bin=$(cd "$bin" && pwd)
runs=("0.1 0.05" "0.05 0.1" "0.05 0.05" "0.05 0.025" "0.025 0.05")
declare -A meshed=()
for run in "${runs[@]}"; do
  read -r h dt <<<"$run"
  mesh=$work/mesh-$h
  if [[ -z ${meshed[$h]:-} ]]; then
    rm -rf "$mesh"
    cp -r "$root/cases/slipWeakeningInjection" "$mesh"
    (cd "$mesh" && ./Allclean >/dev/null && ./Allmesh -h "$h" >/dev/null)
    "$bin/splitFractureNodes" -case "$mesh" >"$mesh/log.splitFractureNodes" 2>&1
    meshed[$h]=1
  fi
  d=$work/h$h-dt$dt
  rm -rf "$d"
  mkdir -p "$d"
  cp -r "$mesh/0" "$mesh/constant" "$mesh/system" "$d"/
  times=$(/usr/bin/python3 -c "
coarse = [0.25 * i for i in range(1, 23)]            # 0.25 ... 5.5
n = round(1 / $dt)
fine = [5.5 + k / n for k in range(1, round(n) + 1)]   # 5.5 + dt ... 6.5
print(' '.join(f'{t:.10g}' for t in coarse + fine))")
  /usr/bin/python3 - "$d/system/controlDict" "$times" <<'PY'
import re, sys
path, times = sys.argv[1], sys.argv[2]
text = open(path).read()
new, n = re.subn(r"^times\s*\([^)]*\);", f"times ({times});", text, flags=re.M)
assert n == 1, f"{path}: no times list"
open(path, "w").write(new)
PY
  rc=0
  /usr/bin/time -f "%e %U %S" -o "$d/time" "$bin/frictionSolver" -case "$d" >"$d/log.frictionSolver" 2>&1 || rc=$?
  ((rc == 0 || rc == 3)) || echo "slipWeakeningStudy: h $h dt $dt: frictionSolver exit status $rc" >&2
  /usr/bin/python3 "$root/cases/slipWeakeningInjection/gg12Check.py" "$d" >"$d/gg12.dat" || true
done

/usr/bin/python3 - "$work" "${runs[@]}" <<'PY'
import re, sys
work, runs = sys.argv[1], [r.split() for r in sys.argv[2:]]
FOLD = 4.914
res = {}
for h, dt in runs:
    d = f"{work}/h{h}-dt{dt}"
    wall, user, system = map(float, open(f"{d}/time").read().split()[-3:])
    steps = sum(1 for l in open(f"{d}/log.frictionSolver") if l.startswith("Time = "))
    text = open(f"{d}/gg12.dat").read()
    m = re.search(r"fold from the patch stiffness: t = \S+ s, X = (\S+)", text)
    X = float(m.group(1)) if m else float("nan")
    err, last, nucl, ks = 0.0, None, None, []
    for l in text.splitlines():
        f = l.split()
        if l.startswith("#") or len(f) < 5 or not re.fullmatch(r"[0-9.eE+-]+", f[0]):
            continue
        if f[-2] == "converged":
            last = f[0]
            scale = float(f[1]) / float(f[0]) ** 0.5
            if f[-1] != "-" and nucl is None:
                ks.append((float(f[0]), float(f[-1])))
            if len(f) == 7:  # on the lower branch: time X a_h a_ref bound status k
                err = max(err, abs(float(f[2]) - float(f[3])))
        elif f[-2] == "nucleation" and nucl is None:
            nucl = f[0]
    note = ""
    if X != X and len(ks) >= 2:
        # gg12Check's k^2 extrapolation through the last two converged steps has no root when
        # their slipping patch is the same (k constant while no node joins, here when dt is
        # shorter than the time a node takes to join): through the last converged step and the
        # latest one with a larger k (the previous patch) instead.
        (t2, k2), earlier = ks[-1], [s for s in ks[:-1] if s[1] > ks[-1][1] * 1.01]
        if earlier:
            t1, k1 = earlier[-1]
            tFold = t2 + k2 ** 2 * (t2 - t1) / (k1 ** 2 - k2 ** 2)
            X = scale * tFold ** 0.5  # X = sqrt(4 alpha t)/a_w
            note = f" (k equal in the last two steps; from t = {t1:g}, {t2:g})"
    res[(h, dt)] = (steps, wall, user + system, X, err, last, nucl, note)
base = res[("0.05", "0.05")]
print("| h [m] | Δt near the fold [s] | steps | wall [s] | ratio | CPU [s] | ratio | fold X (patch stiffness) "
      "| error vs 4.914 | max lower-branch error [a_w] | last converged [s] | nucleation [s] |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for h, dt in runs:
    steps, wall, cpu, X, err, last, nucl, note = res[(h, dt)]
    print(f"| {h} | {dt} | {steps} | {wall:.1f} | {wall / base[1]:.2f} | {cpu:.1f} | {cpu / base[2]:.2f} | "
          f"{X:.4f}{note} | {100 * (X / FOLD - 1):+.2f} % | {err:.3f} | {last} | {nucl} |")
PY
