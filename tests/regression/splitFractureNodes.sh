#!/usr/bin/env bash
# Regression scenarios for splitFractureNodes on copies of the real cases.
# Usage: splitFractureNodes.sh BINARY SOURCE_DIR WORK_DIR SCENARIO
# (frictionSolver is taken from the folder of BINARY, for the scenarios that solve.)
set -uo pipefail
bin=$1 src=$2 work=$3 scenario=$4
solver=$(dirname "$bin")/frictionSolver
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

solve() {  # run frictionSolver; sets out and rc
  out=$("$solver" "$@" 2>&1); rc=$?
  printf '%s\n' "$out" | tail -n 5
}

# gmshCase NAME: a copy of inclinedCrack whose .geo the caller edits with mesh (below); a
# coarse crack size keeps the solves to a fraction of a second.
gmshCase() {
  copyCase inclinedCrack
  mv "$work/inclinedCrack" "$work/$1"
  c=$work/$1 geo=$work/$1/constant/mesh/inclinedCrack.geo
}
mesh() {  # mesh the case's .geo with gmsh (h = a/4)
  (cd "$c/constant/mesh" &&
    gmsh -2 -format msh41 -setnumber h 0.0125 inclinedCrack.geo -o inclinedCrack.msh >gmsh.log 2>&1) ||
    fail "gmsh failed: $(tail -3 "$c/constant/mesh/gmsh.log")"
}
timeFolders() { (cd "$1" && ls -d [0-9]* 2>/dev/null | grep -vx 0); }

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
physicalPoint)
  # gmsh writes a node for a Physical Point that no surface embeds: a vertex no triangle
  # uses. It once passed the split and crashed the solver (double free, exit 134).
  gmshCase physicalPoint
  printf '%s\n' 'Point(20) = {0.2, 0.8, 0};' 'Physical Point("probe", 7) = {20};' >>"$geo"
  mesh
  grep -q '"probe"' "$c/constant/mesh/inclinedCrack.msh" || fail "gmsh wrote no probe point"
  run -case "$c"
  ((rc == 0)) || fail "split: exit code $rc"
  expect "$out" "unused vertices:           1 dropped from $c/constant/mesh/inclinedCrack.msh"
  expect "$out" "at (0.2 0.8)"
  solve -case "$c"
  ((rc == 0)) || fail "solve: exit code $rc (134 = the old crash)"
  expect "$out" "End"
  ;;
hiddenCut)
  # The square meshed as two surfaces whose common side x = 0.2 is drawn twice (own points,
  # own lines, never merged): a cut the file does not show. Both lips are also unlabelled.
  gmshCase hiddenCut
  cat >"$geo" <<'GEO'
Mesh.MeshSizeMin = 0.05; Mesh.MeshSizeMax = 0.05;
Point(1) = {0, 0, 0}; Point(2) = {0.2, 0, 0}; Point(3) = {0.2, 1, 0}; Point(4) = {0, 1, 0};
Point(5) = {0.2, 0, 0}; Point(6) = {1, 0, 0}; Point(7) = {1, 1, 0}; Point(8) = {0.2, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Point(9) = {0.475, 0.456699, 0}; Point(10) = {0.525, 0.543301, 0};
Line(9) = {9, 10}; Curve{9} In Surface{2};
Physical Curve("bottom", 1) = {1, 5};
Physical Curve("right", 2) = {6};
Physical Curve("top", 3) = {3, 7};
Physical Curve("left", 4) = {4};
Physical Curve("crack", 5) = {9};
Physical Surface("body", 1) = {1, 2};
GEO
  mesh
  run -case "$c"
  ((rc == 1)) || fail "hidden cut: exit code $rc, expected 1"
  expect "$out" "$c/constant/mesh/inclinedCrack.msh: "
  expect "$out" "pairs of vertices lie at the same place"
  expect "$out" "(0.2 "
  expect "$out" "allowCoincidentNodes yes;"
  [[ ! -e $c/constant/splitMesh ]] || fail "output written despite the error"
  echo 'allowCoincidentNodes yes;' >>"$c/system/meshDict"
  run -case "$c"
  ((rc == 1)) || fail "unlabelled lips: exit code $rc, expected 1"
  expect "$out" "boundary edges (total length 2) have no label"
  expect "$out" "defaultPatch <name>;"
  [[ ! -e $c/constant/splitMesh ]] || fail "output written despite the error"
  echo 'defaultPatch cut;' >>"$c/system/meshDict"
  run -case "$c"
  ((rc == 0)) || fail "accepted cut: exit code $rc"
  expect "$out" "coincident nodes:          21 pairs, allowed by allowCoincidentNodes"
  expect "$out" "unlabelled boundary edges: 40, in patch cut (defaultPatch)"
  expect "$out" "cut             6       40      2             boundary"
  # 0/D must name the new patch like any other.
  solve -case "$c"
  ((rc == 1)) || fail "solve without a condition for 'cut': exit code $rc, expected 1"
  expect "$out" "cut"
  # (With 'cut' free the part right of the cut would float in x: that is what the hidden cut
  # did unasked. Holding the lips in x keeps both parts in place.)
  sed -i 's/^    right   { type free; }/    right   { type free; }\n    cut     { type fixedDisplacement; components (x); value (0 0); }/' "$c/0/D"
  solve -case "$c"
  ((rc == 0)) || fail "solve: exit code $rc"
  ;;
unlabelledEdge)
  # The right side without its Physical Curve: refused; 'defaultPatch right' (free in 0/D)
  # then gives exactly the result of the labelled mesh.
  gmshCase labelled
  mesh
  run -case "$c"; ((rc == 0)) || fail "labelled split: exit code $rc"
  solve -case "$c"; ((rc == 0)) || fail "labelled solve: exit code $rc"
  labelled=$c
  gmshCase unlabelledEdge
  sed -i '/^Physical Curve("right", 2)/d' "$geo"
  mesh
  run -case "$c"
  ((rc == 1)) || fail "exit code $rc, expected 1"
  expect "$out" "$c/constant/mesh/inclinedCrack.msh: "
  expect "$out" "boundary edges (total length 1) have no label: (1 "
  expect "$out" "in $c/system/meshDict"
  [[ ! -e $c/constant/splitMesh ]] || fail "output written despite the error"
  echo 'defaultPatch right;' >>"$c/system/meshDict"
  run -case "$c"
  ((rc == 0)) || fail "defaultPatch: exit code $rc"
  expect "$out" "in patch right (defaultPatch)"
  solve -case "$c"; ((rc == 0)) || fail "solve: exit code $rc"
  # Same mesh, same conditions: the same numbers (the new patch only changes a label).
  cmp "$labelled/1/fractures/crack.dat" "$c/1/fractures/crack.dat" ||
    fail "defaultPatch right gives another result than the labelled right side"
  ;;
staleSplitMesh)
  # frictionSolver once ran an old split mesh after ./Allmesh: it must refuse it.
  gmshCase staleSplitMesh
  mesh
  run -case "$c"; ((rc == 0)) || fail "split: exit code $rc"
  expect "$(cat "$c/constant/splitMesh")" 'meshHash    "fnv1a64:'
  staleRefused() {  # staleRefused WHAT: the solver refuses, names the fix, writes nothing
    solve -case "$c"
    ((rc == 1)) || fail "$1: exit code $rc, expected 1"
    expect "$out" "$c/constant/splitMesh: "
    expect "$out" "$2"
    expect "$out" "splitFractureNodes -case $c -overwrite"
    [[ -z $(timeFolders "$c") ]] || fail "$1: time folders written: $(timeFolders "$c")"
    [[ ! -e $c/postProcessing ]] || fail "$1: postProcessing written"
  }
  # A new mesh (as ./Allmesh -h makes).
  (cd "$c/constant/mesh" && gmsh -2 -format msh41 -setnumber h 0.025 inclinedCrack.geo \
    -o inclinedCrack.msh >gmsh.log 2>&1) || fail "gmsh failed"
  staleRefused "new mesh" "the mesh file $c/constant/mesh/inclinedCrack.msh changed"
  run -case "$c" -overwrite; ((rc == 0)) || fail "split again: exit code $rc"
  # An edited meshDict (here only a comment: the record is of the bytes).
  echo '// edited' >>"$c/system/meshDict"
  staleRefused "edited meshDict" "$c/system/meshDict changed"
  run -case "$c" -overwrite; ((rc == 0)) || fail "split again: exit code $rc"
  # A split mesh from before the record existed.
  /usr/bin/python3 - "$c/constant/splitMesh" <<'PY' || fail "cannot remove madeFrom"
import re, sys
p = sys.argv[1]
t = open(p).read()
t2 = re.sub(r"madeFrom\s*\{[^}]*\}\s*", "", t)
assert t2 != t
open(p, "w").write(t2)
PY
  staleRefused "no record" "does not record which mesh"
  run -case "$c" -overwrite; ((rc == 0)) || fail "split again: exit code $rc"
  solve -case "$c"
  ((rc == 0)) || fail "current split mesh: exit code $rc"
  ;;
tetrahedralMesh)
  # A 3D mesh (gmsh -3, a cube with an embedded fault square) is read, checked, split and
  # summarised; frictionSolver refuses the 3D split mesh.
  copyCase paperBenchmark; c=$work/paperBenchmark
  cat >"$c/constant/mesh/cube.geo" <<'GEO'
lc = 0.5;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
out[] = Extrude {0, 0, 1} { Surface{1}; };
Point(101) = {0.25, 0.25, 0.5, lc}; Point(102) = {0.75, 0.25, 0.5, lc};
Point(103) = {0.75, 0.75, 0.5, lc}; Point(104) = {0.25, 0.75, 0.5, lc};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104}; Plane Surface(101) = {101};
Surface{101} In Volume{out[1]};
Physical Surface("outside", 1) = {1, out[0], out[2], out[3], out[4], out[5]};
Physical Surface("fault", 5) = {101};
Physical Volume("rock", 2) = {out[1]};
GEO
  (cd "$c/constant/mesh" && gmsh -3 -format msh41 cube.geo -o cube.msh >gmsh.log 2>&1) ||
    fail "gmsh failed: $(tail -3 "$c/constant/mesh/gmsh.log")"
  sed -i -e 's#"constant/mesh/square.msh"#"constant/mesh/cube.msh"#' \
    -e '/^patches/,/^}/c\patches { outside 1; fault 5; }' -e 's/^fractures .*/fractures (fault);/' \
    "$c/system/meshDict"
  run -case "$c"
  ((rc == 0)) || fail "exit code $rc"
  expect "$out" "(gmsh .msh 4.1, 3D)"
  expect "$out" "volume:      1"
  expect "$out" "fault           5"
  expect "$out" "    unlabelled boundary faces: 0"
  # The square [1/4, 3/4]² at z = 1/2 lies inside the cube: its rim is the tip line (single
  # nodes), only its inner nodes are duplicated; n_Γ = (0, 0, −1) (Ω⁺ above).
  expect "$out" "Fracture fault (label 5)"
  expect "$out" "area:         0.25"
  expect "$out" "tip line:     2 (length of its edge inside the body)"
  expect "$out" "boundary 0; tips"
  expect "$out" "triangles with all three vertices on the tip line (no jump there)"
  expect "$out" "normal:       (0 0 -1) area-weighted mean"
  line=$(grep "nodes:" <<<"$out" | head -1)
  [[ $line =~ nodes:\ +([0-9]+)\ \(duplicated\ ([0-9]+):\ interior\ ([0-9]+),\ boundary\ 0\;\ tips\ ([0-9]+)\) ]] ||
    fail "bad nodes line: $line"
  ((BASH_REMATCH[1] == BASH_REMATCH[2] + BASH_REMATCH[4] && BASH_REMATCH[2] == BASH_REMATCH[3] &&
    BASH_REMATCH[2] > 0 && BASH_REMATCH[4] > 0)) || fail "node counts do not add up: $line"
  line=$(grep -A2 "^Split mesh" <<<"$out" | grep "points:")
  [[ $line == *"(+${BASH_REMATCH[2]})"* ]] || fail "split mesh points: $line"
  [[ -f $c/constant/splitMesh ]] || fail "constant/splitMesh not written"
  grep -q "^dimension *3;" "$c/constant/splitMesh" || fail "constant/splitMesh lacks 'dimension 3;'"
  # The solver reads the 3D split mesh and refuses the copied 2D case's plane-strain key with
  # the 3D reason (exit 1, nothing written).
  solve -case "$c"
  ((rc == 1)) || fail "frictionSolver on a 3D case with planeStress: exit code $rc (expected 1)"
  expect "$out" "mechanicalProperties:"
  expect "$out" "key 'planeStress' has no meaning in 3D"
  [[ -n $(timeFolders "$c") ]] && fail "frictionSolver wrote a time folder"
  # The work folders hold 2D results that are compared across builds: leave none here.
  rm -rf "$work"/*
  ;;
faultNetwork3d)
  # Three fault surfaces meeting along curves (tests/regression/cases/faultNetworkBox, gmsh
  # boolean fragments): 'crossing' passes through 'main', 'abutting' ends on it. Every node of
  # an intersection curve has one copy per sector; the summary lists the curves; frictionSolver
  # (P1) holds the abutting fault's nodes on the curve (state junction) and lets the others slip.
  cp -r "$src/tests/regression/cases/faultNetworkBox" "$work/"; c=$work/faultNetworkBox
  "$c/Allclean" >/dev/null
  run -case "$c"
  ((rc == 0)) || fail "exit code $rc"
  expect "$out" "Intersections: 2"
  expect "$out" "    abutting: 'abutting' ends on 'main'; length 0.6, 5 nodes, from (0.75 0.2 0.5) to (0.75 0.8 0.5)"
  expect "$out" "    crossing: 'main' and 'crossing'; length 0.6, 5 nodes, from (0.45 0.2 0.5) to (0.45 0.8 0.5)"
  expect "$out" "meeting:      6 nodes passing through, 0 ending on another fault (held)"
  expect "$out" "meeting:      0 nodes passing through, 3 ending on another fault (held)"
  # Copies: 4 at the three inner nodes of the crossing curve, 3 at those of the abutting one.
  expect "$out" "points:     466 (+60)"
  solve -case "$c"
  ((rc == 0)) || fail "frictionSolver: exit code $rc"
  held=$(grep -c ' junction$' "$c/1/fractures/abutting.dat")
  ((held == 3)) || fail "abutting.dat: $held nodes in state junction (3 expected)"
  for f in main crossing; do
    slipping=$(grep -c ' slip$' "$c/1/fractures/$f.dat")
    ((slipping > 0)) || fail "$f.dat: no node slips"
  done
  # The tables say where each fault meets the others (after the frame line), and each fault's
  # .vtp has the point array 'intersection'.
  expect "$(sed -n 4p "$c/1/fractures/abutting.dat")" "# intersection (abutting) with 'main', 5 nodes from (0.75 0.2 0.5) to (0.75 0.8 0.5), length 0.6: ends on it, its jump held at 3 nodes (state junction)"
  expect "$(sed -n 4,5p "$c/1/fractures/main.dat")" "# intersection (crossing) with 'crossing', 5 nodes from (0.45 0.2 0.5) to (0.45 0.8 0.5), length 0.6: passes through"
  expect "$(sed -n 4p "$c/1/fractures/crossing.dat")" "# intersection (crossing) with 'main', 5 nodes from (0.45 0.2 0.5) to (0.45 0.8 0.5), length 0.6: passes through"
  for f in main crossing abutting; do
    grep -qa 'Name="intersection"' "$c/VTK/fractures/${f}_1.vtp" || fail "${f}_1.vtp: no array intersection"
  done
  ;;
shallowIntersection3d)
  # Stability (issue #31): two fault surfaces crossing at 10° (faultNetworkBox/constant/mesh/
  # shallow.geo, ~2000 tetrahedra, meshed here): the thin wedges between them split into four
  # sectors per node, and frictionSolver runs, converges at every step and stays finite.
  cp -r "$src/tests/regression/cases/faultNetworkBox" "$work/"; c=$work/faultNetworkBox
  "$c/Allclean" >/dev/null
  (cd "$c/constant/mesh" &&
    gmsh -3 -format msh41 -setnumber angle 10 -setnumber h 0.15 shallow.geo -o network.msh >gmsh.log 2>&1) ||
    fail "gmsh failed: $(tail -3 "$c/constant/mesh/gmsh.log")"
  sed -i 's/main 5; crossing 6; abutting 7;/main 5; shallow 6;/; s/fractures (main crossing abutting);/fractures (main shallow);/' \
    "$c/system/meshDict"
  sed -i 's/^crossing$/shallow/; /^abutting$/,/^}/d' "$c/constant/fractureProperties"
  run -case "$c"
  ((rc == 0)) || fail "exit code $rc"
  expect "$out" "Intersections: 1"
  expect "$out" "    crossing: 'main' and 'shallow'; length 0.6"
  solve -case "$c"
  ((rc == 0)) || fail "frictionSolver: exit code $rc"
  converged=$(grep -c '^Time = .* converged ' <<<"$out")
  ((converged == 4)) || fail "$converged of 4 steps converged"
  for f in main shallow; do
    grep -qi 'nan\|inf' "$c/1/fractures/$f.dat" && fail "$f.dat: a value is not finite"
    slipping=$(grep -c ' slip$' "$c/1/fractures/$f.dat")
    ((slipping > 0)) || fail "$f.dat: no node slips"
    expect "$(sed -n 4p "$c/1/fractures/$f.dat")" "# intersection (crossing) with '"
  done
  ;;
faultNetwork3dP2)
  # The faults of faultNetwork3d in P2: the mid-edge nodes on the curves are junction nodes
  # too. 'abutting' is held at its 3 inner vertices and the 4 mid-edge nodes of the curve;
  # 'main' and 'crossing' slip; every .vtp has the array 'intersection'.
  cp -r "$src/tests/regression/cases/faultNetworkBox" "$work/"; c=$work/faultNetworkBox
  "$c/Allclean" >/dev/null
  sed -i 's/^elementOrder .*/elementOrder    2;/' "$c/system/frictionSolution"
  run -case "$c"
  ((rc == 0)) || fail "exit code $rc"
  solve -case "$c"
  ((rc == 0)) || fail "frictionSolver: exit code $rc"
  expect "$out" "converged"
  held=$(grep -c ' junction$' "$c/1/fractures/abutting.dat")
  ((held == 7)) || fail "abutting.dat: $held nodes in state junction (7 expected)"
  for f in main crossing; do
    slipping=$(grep -c ' slip$' "$c/1/fractures/$f.dat")
    ((slipping > 0)) || fail "$f.dat: no node slips"
  done
  for f in main crossing abutting; do
    grep -qa 'Name="intersection"' "$c/VTK/fractures/${f}_1.vtp" || fail "${f}_1.vtp: no array intersection"
  done
  ;;
joinedFaults3d)
  # A fault cut along a line into two ('west' and 'east', ending together: joined) equals the
  # uncut one ('main') on the same mesh (faultNetworkBox/constant/mesh/joined.geo), P1 and P2,
  # with the cut line from tip line to tip line and reaching the free outer boundary: the
  # split summary reports the curve, and the tables' slips agree to the tables' 10 digits;
  # east's .vtp (P1, tip to tip) has the line's nodes from west's table.
  for across in 0 1; do
    for order in 1 2; do
      for cut in 0 1; do
        c=$work/across$across-P$order-cut$cut
        cp -r "$src/tests/regression/cases/faultNetworkBox" "$c"
        "$c/Allclean" >/dev/null
        gmsh -3 -format msh41 -setnumber cut $cut -setnumber across $across \
          "$c/constant/mesh/joined.geo" -o "$c/constant/mesh/network.msh" >"$c/gmsh.log" 2>&1 ||
          fail "gmsh failed: $(tail -3 "$c/gmsh.log")"
        sed -i 's/^elementOrder .*/elementOrder    2;/' "$c/system/frictionSolution"
        ((order == 1)) && sed -i 's/^elementOrder .*/elementOrder    1;/' "$c/system/frictionSolution"
        sed -i 's/^deltaT .*/deltaT          1;/' "$c/system/controlDict"
        ((across + order == 1)) || sed -i 's/^writeVTK .*/writeVTK        no;/' "$c/system/controlDict"
        if ((cut)); then
          sed -i 's/main 5; crossing 6; abutting 7;/west 5; east 6;/; s/fractures (main crossing abutting);/fractures (west east);/' "$c/system/meshDict"
          sed -i 's/^main$/west/; s/^crossing$/east/; /^abutting$/,/^}/d' "$c/constant/fractureProperties"
        else
          sed -i 's/main 5; crossing 6; abutting 7;/main 5;/; s/fractures (main crossing abutting);/fractures (main);/' "$c/system/meshDict"
          sed -i '/^crossing$/,/^}/d; /^abutting$/,/^}/d' "$c/constant/fractureProperties"
        fi
        run -case "$c"
        ((rc == 0)) || fail "$c: exit code $rc"
        if ((cut)); then
          expect "$out" "Intersections: 1"
          expect "$out" "    joined: 'west' and 'east' end together; length $( ((across)) && echo 1 || echo 0.6),"
        fi
        solve -case "$c"
        ((rc == 0)) || fail "$c: frictionSolver: exit code $rc"
      done
      uncut=$work/across$across-P$order-cut0/1/fractures cut=$work/across$across-P$order-cut1/1/fractures
      expect "$(sed -n 4p "$cut/west.dat")" "# intersection (joined) with 'east'"
      if ((across + order == 1)); then
        # east's .vtp: its table's rows and the 5 nodes of the line, whose rows are in west's
        # (3 joined, 2 tips), which its triangles use.
        rows=$(grep -c '^[^#]' "$cut/east.dat")
        grep -qa "NumberOfPoints=\"$((rows + 5))\"" "$work/across0-P1-cut1/VTK/fractures/east_1.vtp" ||
          fail "east_1.vtp: not $((rows + 5)) points"
      fi
      expect "$(sed -n 4p "$cut/east.dat")" "ends together with it ($( ((across)) && echo 7 || echo 3) nodes joined, their rows in 'west'; 0 held"
      /usr/bin/python3 - "$uncut/main.dat" "$cut/west.dat" "$cut/east.dat" <<'PY' || fail "across $across, P$order: the cut fault differs from the uncut one"
import sys
def read(path):
    rows = {}
    for line in open(path):
        if line.startswith("# x "):
            cols = line[2:].split()
        elif line.strip() and not line.startswith("#"):
            v = line.split()
            key = tuple(round(float(x), 9) for x in v[:3])
            rows[key] = ([float(v[cols.index(c)]) for c in ("slipX", "slipY", "slipZ")], v[-1])
    return rows
whole = read(sys.argv[1])
largest = max(max(abs(s) for s in slip) for slip, _ in whole.values())
seen, worst = 0, 0.0
for piece in sys.argv[2:]:
    for key, (slip, state) in read(piece).items():
        ref, refState = whole[key]
        worst = max(worst, max(abs(a - b) for a, b in zip(slip, ref)) / largest)
        assert state == refState, (key, state, refState)
        seen += 1
print(f"{seen} of {len(whole)} nodes compared, largest slip {largest:.4g} m, "
      f"largest difference / largest slip {worst:.2g}")
assert seen == len(whole) and largest > 0 and worst < 1e-8
PY
    done
  done
  ;;
*) fail "unknown scenario" ;;
esac
echo "PASS [$scenario]"
