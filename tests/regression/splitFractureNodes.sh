#!/usr/bin/env bash
# Regression scenarios for splitFractureNodes on copies of the real cases.
# Usage: splitFractureNodes.sh BINARY SOURCE_DIR WORK_DIR SCENARIO
set -uo pipefail
bin=$1 src=$2 work=$3 scenario=$4
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL [$scenario]: $*"; exit 1; }
expect() { grep -qF -- "$2" <<<"$1" || fail "output lacks '$2'"; }

copyCase() {  # copy a case without anything a run made
  cp -r "$src/cases/$1" "$work/$1"
  "$work/$1/Allclean" >/dev/null
}

run() {  # run the utility; sets out (stdout+stderr) and rc
  out=$("$bin" "$@" 2>&1); rc=$?
  printf '%s\n' "$out"
}

case $scenario in
paperBenchmark)
  copyCase paperBenchmark; c=$work/paperBenchmark
  run -case "$c"
  ((rc == 0)) || fail "exit code $rc"
  expect "$out" "Fracture fracture (label 5)"
  # A fracture across the whole width: no tips, every node duplicated, both ends on the
  # boundary (left and right patches), normal (0 -1) from Ω⁺ (above) to Ω⁻.
  line=$(grep "nodes:" <<<"$out" | head -1)
  [[ $line =~ nodes:\ +([0-9]+)\ \(duplicated\ ([0-9]+),\ tips\ 0\) ]] || fail "bad nodes line: $line"
  [[ ${BASH_REMATCH[1]} == "${BASH_REMATCH[2]}" ]] || fail "not every fracture node duplicated"
  expect "$out" "start:        (0 0.5) on the outer boundary, patch left (duplicated)"
  expect "$out" "end:          (1 0.5) on the outer boundary, patch right (duplicated)"
  expect "$out" "normal:       (0 -1)"
  expect "$out" "length:       1"
  expect "$out" "End"
  [[ -f $c/constant/splitMesh ]] || fail "constant/splitMesh not written"
  ;;
inclinedCrack)
  copyCase inclinedCrack; c=$work/inclinedCrack
  run -case "$c"
  ((rc == 0)) || fail "exit code $rc"
  expect "$out" "Fracture crack"
  expect "$out" "tips 2)"
  expect "$out" "tip inside the body (single node)"
  # The crack is 2a = 0.1 m long.
  len=$(grep "length:" <<<"$out" | tail -1 | awk '{print $2}')
  awk -v l="$len" 'BEGIN { exit !(l > 0.1 - 1e-9 && l < 0.1 + 1e-9) }' || fail "crack length $len != 0.1"
  ;;
refuseSecondRun)
  copyCase paperBenchmark; c=$work/paperBenchmark
  run -case "$c"; ((rc == 0)) || fail "first run failed"
  sum=$(md5sum <"$c/constant/splitMesh")
  run -case "$c"
  ((rc != 0)) || fail "second run did not refuse"
  expect "$out" "already split"
  expect "$out" "-overwrite"
  [[ $(md5sum <"$c/constant/splitMesh") == "$sum" ]] || fail "second run changed the split mesh"
  run -case "$c" -overwrite
  ((rc == 0)) || fail "-overwrite failed"
  [[ $(md5sum <"$c/constant/splitMesh") == "$sum" ]] || fail "-overwrite split differently (split twice?)"
  ;;
badMeshDict)
  copyCase paperBenchmark; c=$work/paperBenchmark
  sed -i 's/^fractures/fractrues/' "$c/system/meshDict"
  lineNo=$(grep -n '^fractrues' "$c/system/meshDict" | cut -d: -f1)
  run -case "$c"
  ((rc == 1)) || fail "exit code $rc, expected 1"
  expect "$out" "system/meshDict:"
  [[ $lineNo ]] && expect "$out" ":$lineNo"
  expect "$out" "fractures"
  [[ ! -e $c/constant/splitMesh ]] || fail "output written despite the error"
  ;;
unknownFracture)
  copyCase paperBenchmark; c=$work/paperBenchmark
  sed -i 's/^fractures .*/fractures   (fractur);/' "$c/system/meshDict"
  run -case "$c"
  ((rc == 1)) || fail "exit code $rc, expected 1"
  expect "$out" "system/meshDict:"
  expect "$out" "'fractur' is not a patch"
  expect "$out" "did you mean 'fracture'"
  [[ ! -e $c/constant/splitMesh ]] || fail "output written despite the error"
  ;;
truncatedMesh)
  copyCase paperBenchmark; c=$work/paperBenchmark
  msh=$(ls "$c"/constant/mesh/*.msh | head -1)
  total=$(wc -l <"$msh")
  head -n $((total / 2)) "$msh" >"$msh.tmp" && mv "$msh.tmp" "$msh"
  run -case "$c"
  ((rc == 1)) || fail "exit code $rc, expected 1"
  expect "$out" "$(basename "$msh"):"
  [[ ! -e $c/constant/splitMesh ]] || fail "output written despite the error"
  ;;
unwritableCase)
  copyCase paperBenchmark; c=$work/paperBenchmark
  rm -rf "$c/constant/splitMesh"
  if [[ $(id -u) -eq 0 ]]; then
    # root ignores permissions: make constant/ a file so that nothing can be created in it.
    mv "$c/constant" "$c/constant.real"
    cp -r "$c/constant.real" "$c/constantCopy"
    sed -i "s#constant/mesh#constantCopy/mesh#" "$c/system/meshDict"
    echo "not a folder" >"$c/constant"
  else
    chmod a-w "$c/constant"
  fi
  run -case "$c"
  ((rc == 1)) || fail "exit code $rc, expected 1"
  expect "$out" "constant"
  ;;
foamDictionaryReads)
  copyCase paperBenchmark; c=$work/paperBenchmark
  run -case "$c"; ((rc == 0)) || fail "split failed"
  export WM_PROJECT_DIR=/usr/share/openfoam
  command -v foamDictionary >/dev/null || fail "foamDictionary not installed (package openfoam)"
  keys=$(foamDictionary "$c/constant/splitMesh" -keywords 2>&1) || fail "foamDictionary cannot parse: $keys"
  for k in points origin triangles regions patches fractures; do expect "$keys" "$k"; done
  label=$(foamDictionary "$c/constant/splitMesh" -entry fractures/fracture/label -value 2>&1)
  [[ $label == 5 ]] || fail "fractures/fracture/label read back as '$label'"
  ;;
*) fail "unknown scenario" ;;
esac
echo "PASS [$scenario]"
