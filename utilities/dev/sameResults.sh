#!/bin/bash
# sameResults.sh A B: are two trees of solver outputs the same, byte for byte?
#
# For refactorings that must keep every result (the 3D redesign keeps every 2D result byte for
# byte): run the regression and stability suites with the old and the new build and compare
# their work folders (build/tests/regression/work, build/tests/stability/work). Every file
# must be identical, up to absolute paths into the build tree (a split mesh records the mesh
# it was made from, and two builds live in different folders), except
#   * logs (log.*, *.log): compared after removing what measures time or memory (seconds,
#     "~… left", peak memory, dates), which differs from run to run of the same binary;
#     and after writing every absolute path into the work folders or a build tree as <work>, <build>/ (two builds
#     live in different folders);
#   * gmsh's own log (gmsh.log, log.gmsh: it stamps the date and the source path);
#   * the runs that a signal or a kill stops at a moment the test does not fix (where the
#     run stops depends on the machine's load): noDataLoss/{sigint,sigterm},
#     noDataLoss/killRestart/{kill*,random}, and the logs of solver/*-secondSignal and
#     solver/*-controlDictDeleted (the warning's place among the step lines).
# Prints "same" and exits 0, or lists the files that differ and exits 1 (files only in B,
# e.g. new tests' outputs, are listed and counted but are not a difference).
set -u
[ $# -eq 2 ] || { echo "usage: $0 DIR_A DIR_B" >&2; exit 2; }
a=$1 b=$2
[ -d "$a" ] && [ -d "$b" ] || { echo "$0: both arguments must be folders" >&2; exit 2; }
normalise() {
  # The factor's size line and the peak memory are costs, like the timings (the solver logs
  # them since 2026-11-25; an older tree has neither).
  sed -E -e '/^Factor: /d' -e 's/, peak memory [0-9.]+ GB//' \
    -e 's/[0-9.]+(e[-+]?[0-9]+)? ?(s|ms|MB|GB|MiB|GiB)\b/<t>/g' \
    -e 's/~[^]]*left/~<t> left/g' -e "s#/[^ :'\"]*/tests/(regression|stability)/work#<work>#g" -e "s#/[^ :'\"]*/build/#<build>/#g" -e 's/[0-9]{4}-[0-9]{2}-[0-9]{2}[ T][0-9:.]+/<date>/g' "$1"
}
onlyPaths() { sed -E -e "s#/[^ :'\"]*/tests/(regression|stability)/work#<work>#g" -e "s#/[^ :'\"]*/build/#<build>/#g" "$1"; }
status=0
n=0
newer=
while IFS= read -r -d '' f; do
  rel=${f#"$a"/}
  n=$((n + 1))
  case "$rel" in
    noDataLoss/sigint/* | noDataLoss/sigterm/* | noDataLoss/killRestart/kill* | \
      noDataLoss/killRestart/random/*) continue ;;
    solver/*-secondSignal/log.* | solver/*-controlDictDeleted/log.*) continue ;;
  esac
  if [ ! -e "$b/$rel" ]; then echo "only in $a: $rel"; status=1; continue; fi
  case "$(basename "$rel")" in
    gmsh.log | log.gmsh) continue ;;
    log.* | *.log)
      cmp -s <(normalise "$f") <(normalise "$b/$rel") || { echo "differs: $rel"; status=1; } ;;
    *) cmp -s "$f" "$b/$rel" || cmp -s <(onlyPaths "$f") <(onlyPaths "$b/$rel") ||
      { echo "differs: $rel"; status=1; } ;;
  esac
done < <(find "$a" -type f -print0)
while IFS= read -r -d '' f; do
  rel=${f#"$b"/}
  case "$rel" in
    noDataLoss/sigint/* | noDataLoss/sigterm/* | noDataLoss/killRestart/kill* | \
      noDataLoss/killRestart/random/*) continue ;;
  esac
  [ -e "$a/$rel" ] || { echo "only in $b: $rel"; newer=$((newer + 1)); }
done < <(find "$b" -type f -print0)
[ "$n" -gt 0 ] || { echo "$0: no files in $a" >&2; exit 2; }
# Files only in B (new tests' outputs) are listed but are not a difference: every file of A
# is in B and the same.
[ $status -eq 0 ] && echo "same ($n files${newer:+; $newer more only in $b})"
exit $status
