# Sourced by the regression scripts that run cases/seasBP3 for 250 years (seasBP3.sh,
# faultOperatorHierarchical.sh, faultOperatorSingle.sh): a copy of the case, stopped at 100
# years (before the earthquake near 166 years) and restarted with startFrom latestTime, must
# write the very bytes of the uninterrupted run.
#   bp3RestartSameBytes BIN RESTARTED_CASE UNINTERRUPTED_CASE
# exits the script with a FAIL line otherwise (no restart, a file that differs, or fewer than
# 40 files compared: a check over nothing would pass).
bp3RestartSameBytes() {
  local bin=$1 restarted=$2 full=$3 year=31536000 n=0 f
  (
    cd "$restarted"
    sed -i "s/^endTime .*/endTime $((100 * year));/" system/controlDict
    "$bin/frictionSolver" -case . >log.1 2>&1
    sed -i "s/^endTime .*/endTime $((250 * year));/; s/^startTime /startFrom latestTime;\nstartTime /" system/controlDict
    "$bin/frictionSolver" -case . >log.2 2>&1
  )
  grep -q "^Restarting from time 3.1536e+09" "$restarted/log.2" ||
    { echo "FAIL: no restart at 100 years"; exit 1; }
  for f in $(cd "$full" && find . -type f ! -name 'log.*' ! -name '.*' ! -path ./system/controlDict | sort); do
    cmp -s "$full/$f" "$restarted/$f" || { echo "FAIL: $f differs after the restart"; exit 1; }
    n=$((n + 1))
  done
  ((n > 40)) || { echo "FAIL: only $n files compared"; exit 1; }
  echo "PASS: stopped at 100 years and restarted: $n files byte for byte"
}
