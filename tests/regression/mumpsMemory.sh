#!/usr/bin/env bash
# MUMPS's smaller factors (system/frictionSolution: lowRank, outOfCore, outOfCoreDir; README
# "Running in parallel") on cases/pennyCrack's committed mesh (3D, 5 460 fault values, the
# interface operator S from MUMPS's Schur complement), each run against a full-rank in-core
# mumps run of the same case (parallelCompare.py: every column of every fracture table).
# Usage: mumpsMemory.sh BIN_DIR SOURCE_DIR WORK_DIR SCENARIO
#   lowRank     lowRank 1e-10 gives the full-rank tables to 1e-6 of each column's scale: a block
#               truncated at ε in MUMPS's scaled matrix (entries ≤ 1) perturbs it by about ε, and
#               the solution by at most κ ε, κ the scaled stiffness's condition number, below
#               1e4 on this mesh ((L/h)² = 32²); measured 2.3e-15, for nothing is dropped at
#               1e-10 here. lowRank 1e-2 does compress (the log's share of entries below 100 %)
#               and still converges with S from the low-rank factor, to the slip within 5e-2
#               (measured 1.8e-2: the error of an ε-truncated factor is O(ε)).
#   outOfCore   outOfCore yes (files in a folder of the run's own in the case folder) and
#               outOfCoreDir (a folder given relative to the case, holding a user's file):
#               the same tables to 1e-9 (the same factor, stored on disk), the log says what was
#               written where, and afterwards nothing of the run is left but its outputs: the
#               user's file stays. On 2 ranks (mpirun) with lowRank 1e-10 too: each rank's
#               files and folder removed.
#   outOfCoreAuto  outOfCore auto (the default): in core on this small case, the log saying so
#               with MUMPS's estimate against the memory available; with outOfCoreAbove 1e6 (1 MB,
#               below MUMPS's estimate) out of core, the log saying why and what was written, the
#               same tables to 1e-9 and nothing left behind.
#   badValues   a tolerance out of (0, 1), an out-of-core folder that does not exist, is a file
#               or cannot be written, outOfCoreDir with outOfCore no, outOfCoreAbove with
#               outOfCore yes or ≤ 0, outOfCore neither yes, no nor auto: exit 1, the file, line
#               and key named, nothing written in the case.
set -u
bin=$1 src=$2 work=$3 scenario=$4
fail() { echo "FAIL [mumpsMemory.$scenario]: $*" >&2; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
"$bin/frictionSolver" -listModels | grep -q "linear solvers.*mumps" ||
  fail "this build has no mumps linear solver (FRICTION_MUMPS)"
compare=$src/tests/regression/parallelCompare.py

source "$src/tests/regression/pennyVariants.sh"
# variant NAME 'KEYS': a copy of the case whose linearSolver line is 'linearSolver mumps; KEYS'.
variant() { pennyVariant "$1" mumps "$2"; }
solve() {  # solve NAME [LAUNCHER...]: run it, expect exit 0
  local name=$1
  shift
  "$@" "$bin/frictionSolver" ${1:+-parallel} -case "$work/$name" >"$work/$name.log" 2>&1 ||
    fail "$name: exit $?: $(tail -n 5 "$work/$name.log")"
}
reference() {
  variant full ""
  solve full
}
# wroteInCaseAndCleaned NAME LISTING_BEFORE: the run wrote its factor in a folder of its own in
# the case (the log's Out-of-core line, more than 0 GB), gave the full-rank run's tables to
# 1e-9, and left nothing behind but its outputs.
wroteInCaseAndCleaned() {
  local name=$1 before=$2 left
  grep -qE "^Out-of-core factor: [0-9.e+-]+ GB written to $work/$name/mumpsOutOfCore\.[A-Za-z0-9]{6} \(deleted at the end of the run\)" \
    "$work/$name.log" || fail "$name: no Out-of-core line naming a folder in the case: $(grep -a "^Out" "$work/$name.log")"
  grep -q "^Out-of-core factor: 0 GB" "$work/$name.log" && fail "$name: nothing written to disk"
  python3 "$compare" "$work/full" "$work/$name" || fail "$name: tables differ"
  left=$(comm -13 <(echo "$before") <(listing "$name") | grep -v '^\./1\(/\|$\)\|^\./postProcessing\(/\|$\)')
  [[ -z $left ]] || fail "$name: left behind: $left"
}

case $scenario in
  lowRank)
    reference
    variant blr10 "lowRank 1e-10;"
    solve blr10
    grep -q "linear solver mumps, low-rank factor (BLR) at 1e-10" "$work/blr10.log" ||
      fail "blr10: the settings line does not state the low-rank factor"
    grep -q "^Low-rank factor (BLR, dropping tolerance 1e-10): .* entries of the full-rank" \
      "$work/blr10.log" || fail "blr10: no Low-rank factor line"
    python3 "$compare" --tolerance 1e-6 "$work/full" "$work/blr10" || fail "blr10: tables differ"
    variant blr2 "lowRank 1e-2;"
    solve blr2
    share=$(sed -n 's/^Low-rank factor (BLR, dropping tolerance 0.01): .* (\([0-9.]*\) %).*/\1/p' "$work/blr2.log")
    [[ -n $share ]] || fail "blr2: no Low-rank factor line: $(grep -a "^Factor" "$work/blr2.log")"
    awk -v s="$share" 'BEGIN { exit !(s < 100) }' || fail "blr2: nothing compressed ($share %)"
    python3 "$compare" --tolerance 5e-2 "$work/full" "$work/blr2" || fail "blr2: tables differ"
    echo "lowRank 1e-2 kept $share % of the entries"
    ;;
  outOfCore)
    reference
    variant ooc "outOfCore yes;"
    before=$(listing ooc)
    solve ooc
    wroteInCaseAndCleaned ooc "$before"
    # A folder given relative to the case, with a user's file in it: only that file remains.
    variant oocDir "outOfCore yes; outOfCoreDir \"scratch\";"
    mkdir "$work/oocDir/scratch" && echo keep >"$work/oocDir/scratch/keep.me"
    solve oocDir
    grep -q "written to $work/oocDir/scratch/mumpsOutOfCore\." "$work/oocDir.log" ||
      fail "oocDir: the files did not go to outOfCoreDir: $(grep -a "^Out" "$work/oocDir.log")"
    [[ $(ls -A "$work/oocDir/scratch") == keep.me ]] ||
      fail "oocDir: scratch holds $(ls -A "$work/oocDir/scratch")"
    python3 "$compare" "$work/full" "$work/oocDir" || fail "oocDir: tables differ"
    if command -v mpirun >/dev/null; then
      variant ooc2 "outOfCore yes; lowRank 1e-10;"
      before=$(listing ooc2)
      solve ooc2 mpirun -np 2
      python3 "$compare" --tolerance 1e-6 "$work/full" "$work/ooc2" || fail "ooc2: tables differ"
      left=$(comm -13 <(echo "$before") <(listing ooc2) | grep -v '^\./1\(/\|$\)\|^\./postProcessing\(/\|$\)')
      [[ -z $left ]] || fail "ooc2: left behind on 2 ranks: $left"
    fi
    ;;
  outOfCoreAuto)
    reference
    grep -qE "^Factor: outOfCore auto: in core, MUMPS's in-core estimate [0-9.e+-]+ GB <= [0-9.e+-]+ GB available$" \
      "$work/full.log" || fail "full: no in-core verdict of outOfCore auto: $(grep -a "^Factor" "$work/full.log")"
    grep -q "^Out-of-core factor" "$work/full.log" && fail "full: went out of core"
    variant oocAuto "outOfCoreAbove 1e6;"
    before=$(listing oocAuto)
    solve oocAuto
    grep -qE "^Factor: outOfCore auto: out of core, MUMPS's in-core estimate [0-9.e+-]+ GB > 0.001 GB \(outOfCoreAbove\)$" \
      "$work/oocAuto.log" || fail "oocAuto: no out-of-core verdict: $(grep -a "^Factor" "$work/oocAuto.log")"
    wroteInCaseAndCleaned oocAuto "$before"
    ;;
  badValues)
    n=0
    # bad NAME 'KEYS' LINE_TEXT EXPECTED...: exit 1, file:line and the texts, the case unchanged
    bad() {
      local name=$1 keys=$2
      shift 2
      variant "$name" "$keys"
      pennyRefused "$name" "^linearSolver" "$@"
    }
    bad negative "lowRank -1e-8;" "lowRank" "(0, 1)"
    bad zero "lowRank 0;" "lowRank" "(0, 1)"
    bad missingDir "outOfCore yes; outOfCoreDir \"nowhere\";" "key 'outOfCoreDir'" "/nowhere' is not an existing folder"
    bad fileAsDir "outOfCore yes; outOfCoreDir \"system/controlDict\";" "key 'outOfCoreDir'" "is not an existing folder"
    bad dirWithoutOutOfCore "outOfCore no; outOfCoreDir \"/tmp\";" "key 'outOfCoreDir'" "needs 'outOfCore yes;' or 'outOfCore auto;'"
    bad aboveWithYes "outOfCore yes; outOfCoreAbove 1e9;" "key 'outOfCoreAbove'" "needs 'outOfCore auto;'"
    bad aboveNegative "outOfCoreAbove -1;" "outOfCoreAbove"
    bad outOfCoreWord "outOfCore maybe;" "outOfCore"
    # A folder that cannot be written: /sys refuses even root (EPERM or EROFS).
    if ! mkdir /sys/mumpsMemoryProbe 2>/dev/null; then
      bad unwritable "outOfCore yes; outOfCoreDir \"/sys\";" "key 'outOfCoreDir'" "cannot write in the out-of-core folder '/sys'"
    else
      rmdir /sys/mumpsMemoryProbe
      echo "unwritable: skipped (/sys is writable here)"
    fi
    echo "$n refusals"
    ;;
  *) fail "unknown scenario" ;;
esac
echo "mumpsMemory.$scenario: ok"
