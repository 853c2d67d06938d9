#!/usr/bin/env bash
# What accuracy costs for quasi-dynamic rate-and-state friction (timeIntegration quasiDynamic,
# law rateState). The stick-slip case of tests/regression/quasiDynamic.sh ("events"):
# cases/paperBenchmark's mesh, E = 30 GPa, in-situ σ_n = −10 MPa, τ = 5.5 MPa, the top moved
# sideways at 1e-9 m/s, a velocity-weakening fault (a = 0.01, b = 0.015, L = 1 µm, f₀ = 0.6,
# V₀ = 1e-5 m/s, V_init = 1e-9 m/s, c_s = 3464 m/s), events recurring every ~1.2e5 s with peak
# slip rates ~1.3 m/s, over 4e5 s written every DELTA_T s (default 1000). Varied: the
# integration's relativeTolerance (1e-5 … 1e-10, default 1e-8) with dormandPrince54, and
# bogackiShampine32 at 1e-8. Prints per run: tolerance, scheme, the Runge–Kutta steps in all
# (sum of the step lines' `iterations`), the wall time of frictionSolver [s] and its ratio to
# the default run's (1e-8, dormandPrince54; all measured in this run of the script, one after
# the other), the events (steps whose peakSlipRate, the largest |V| over the step's interval,
# exceeds 0.1 m/s), the mean recurrence interval and its difference from the tightest
# tolerance's, and the second event's peak slip rate.
# An event's time: the integrator does not report when within a written step the peak falls,
# so each event is located by zooming: the run is restarted (byte for byte, tested) from the
# written time before the step that holds the event, over that step alone, written every
# DELTA_T/100, then again from the finer step before the event, written every DELTA_T/10⁴
# (ZOOM="10 0.1" for DELTA_T = 1000). The event's time is the end of the finest step whose
# peakSlipRate exceeds 0.1 m/s (known to ± the finest step). Only the first, unzoomed run is
# timed and counted.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-$root/build/bin}
work=${2:-$root/build/rateStateStudy}
dt=${DELTA_T:-1000}
read -r -a zoom <<<"${ZOOM:-$(/usr/bin/python3 -c "print(f'{$dt / 100:g} {$dt / 1e4:g}')")}"
mkdir -p "$work"
work=$(cd "$work" && pwd)
bin=$(cd "$bin" && pwd)

# The base case: tests/regression/quasiDynamic.sh's "events".
base=$work/base
rm -rf "$base"
source "$root/utilities/frictionStudy/rateStateBlock.sh"
rateStateBlock "$root" "$base" 0.01 0.015 1e-6 1e-9 1e6 1e-3 400000 "$dt"
cd "$base"

# "from to" per written step whose peakSlipRate (largest |V| over its interval) is above
# 0.1 m/s: the time names of its start and end. Usage: events LOG START_TIME_NAME
events() {
  awk -v prev="$2" '/^Time = / {for (i = 1; i <= NF; i++) if ($i == "peakSlipRate") v = $(i + 1)
    if (v > 0.1) print prev, $3; prev = $3}' "$1"
}

runs=("1e-5 dormandPrince54" "1e-6 dormandPrince54" "1e-7 dormandPrince54"
  "1e-8 dormandPrince54" "1e-9 dormandPrince54" "1e-10 dormandPrince54"
  "1e-8 bogackiShampine32")
for run in "${runs[@]}"; do
  read -r tol scheme <<<"$run"
  d=$work/$tol-$scheme
  rm -rf "$d" "$d.zoom"
  cp -r "$base" "$d"
  mkdir -p "$d.zoom"
  cat >"$d/system/frictionSolution" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object frictionSolution; }
elementOrder    1;
timeIntegration { type quasiDynamic; relativeTolerance $tol; scheme $scheme; }
control { gammaRelative 1; optimizer { type semismoothNewton; tolerance 1e-10; maxIterations 100; } }
DICT
  rc=0
  /usr/bin/time -f "%e %U %S" -o "$d/time" "$bin/frictionSolver" -case "$d" >"$d/log.frictionSolver" 2>&1 || rc=$?
  ((rc == 0)) || echo "rateStateStudy: $tol $scheme: frictionSolver exit status $rc (see $d/log.frictionSolver)" >&2
  # Locate each event by zooming into the written step that holds it (restarts, not timed).
  : >"$d/events"
  while read -r from to; do
    src=$d
    for step in "${zoom[@]}"; do
      z=$d.zoom/event$to-step$step
      rm -rf "$z"
      mkdir -p "$z"
      cp -r "$src/0" "$src/constant" "$src/system" "$src/$from" "$z"/
      sed -i "s/^startFrom .*/startFrom latestTime;/; s/^endTime .*/endTime $to;/; s/^deltaT .*/deltaT $step;/" \
        "$z/system/controlDict"
      "$bin/frictionSolver" -case "$z" >"$z/log.frictionSolver" 2>&1 ||
        echo "rateStateStudy: zoom $z failed (see its log.frictionSolver)" >&2
      read -r from to < <(events "$z/log.frictionSolver" "$from" | head -1) ||
        { echo "rateStateStudy: $z: the event is not in the zoomed step" >&2; break; }
      src=$z
    done
    echo "$to" >>"$d/events"
  done < <(events "$d/log.frictionSolver" 0)
  # The written fields are not needed any more (tens of MB per run).
  find "$d" "$d.zoom" -mindepth 1 -maxdepth 2 -type d -regex '.*/[0-9][0-9.e+-]*' ! -name 0 -exec rm -rf {} +
done

/usr/bin/python3 - "$work" "${zoom[*]}" "${runs[@]}" <<'PY'
import sys
work, zoom, runs = sys.argv[1], [float(z) for z in sys.argv[2].split()], [r.split() for r in sys.argv[3:]]
res = {}
for tol, scheme in runs:
    d = f"{work}/{tol}-{scheme}"
    wall, user, system = map(float, open(f"{d}/time").read().split()[-3:])
    steps, peaks, ok = 0, [], 0
    for line in open(f"{d}/log.frictionSolver"):
        if not line.startswith("Time = "):
            continue
        f = line.split()
        steps += int(f[f.index("iterations") + 1])
        ok += "converged" in f
        peak = float(f[f.index("peakSlipRate") + 1])
        if peak > 0.1:
            peaks.append(peak)
    events = [float(t) for t in open(f"{d}/events").read().split()]
    assert len(events) == len(peaks), f"{d}: {len(events)} events located, {len(peaks)} in the log"
    res[(tol, scheme)] = (steps, wall, user + system, events, peaks, ok)
default = res[("1e-8", "dormandPrince54")]
ref = res[("1e-10", "dormandPrince54")][3]
def interval(ev):
    return (ev[-1] - ev[0]) / (len(ev) - 1) if len(ev) >= 2 else float("nan")
print("| relativeTolerance | scheme | written steps converged | Runge–Kutta steps | wall [s] | "
      "ratio | CPU [s] | ratio | events at [s] | recurrence [s] | − tightest's [s] | "
      "2nd event's peak [m/s] |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for tol, scheme in runs:
    steps, wall, cpu, ev, peaks, ok = res[(tol, scheme)]
    diff = interval(ev) - interval(ref)
    p2 = f"{peaks[1]:.4g}" if len(peaks) >= 2 else "-"
    print(f"| {tol} | {scheme} | {ok} | {steps} | {wall:.1f} | {wall / default[1]:.2f} | {cpu:.1f} | "
          f"{cpu / default[2]:.2f} | {' '.join(f'{t:.10g}' for t in ev)} | {interval(ev):.6g} | "
          f"{diff:+.3g} | {p2} |")
print(f"(event times: the end of the finest zoomed step, {zoom[-1]:g} s, whose peak slip rate "
      f"exceeds 0.1 m/s; recurrence: (last - first)/(events - 1))")
PY
