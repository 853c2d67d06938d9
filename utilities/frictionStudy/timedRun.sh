# Sourced by the benchmark scripts: timedRun BIN CASE runs frictionSolver on CASE (its log in
# CASE/log.frictionSolver) and prints its wall time in seconds.
timedRun() {
  local t0 t1
  t0=$(date +%s.%N)
  "$1/frictionSolver" -case "$2" >"$2/log.frictionSolver" 2>&1
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }'
}
