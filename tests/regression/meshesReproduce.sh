#!/usr/bin/env bash
# The committed meshes of the cases are exactly what their generators (FreeFEM .edp, gmsh .geo)
# make with the default parameters, so a case's mesh can never silently drift from its
# script. Usage: meshesReproduce.sh SOURCE_DIR WORK_DIR
set -uo pipefail
src=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

command -v FreeFem++ >/dev/null || fail "FreeFem++ not installed (package freefem++)"
command -v gmsh >/dev/null || fail "gmsh not installed (package gmsh)"
export FF_LOADPATH="/usr/lib/freefem++;./" FF_INCLUDEPATH=/usr/include/freefem++/idp

cp "$src/cases/paperBenchmark/constant/mesh/square.edp" "$work/"
(cd "$work" && FreeFem++ -nw -ns -v 0 square.edp -out square.msh >freefem.log 2>&1) ||
  fail "FreeFem++ failed: $(cat "$work/freefem.log")"
cmp -s "$work/square.msh" "$src/cases/paperBenchmark/constant/mesh/square.msh" ||
  fail "cases/paperBenchmark/constant/mesh/square.msh differs from what square.edp makes; run its Allmesh"

cp "$src/cases/strikeSlipFault/constant/mesh/block.edp" "$work/"
(cd "$work" && FreeFem++ -nw -ns -v 0 block.edp -out block.mesh >freefem3d.log 2>&1) ||
  fail "FreeFem++ failed: $(cat "$work/freefem3d.log")"
cmp -s "$work/block.mesh" "$src/cases/strikeSlipFault/constant/mesh/block.mesh" ||
  fail "cases/strikeSlipFault/constant/mesh/block.mesh differs from what block.edp makes; run its Allmesh"

cp "$src/cases/inclinedCrack/constant/mesh/inclinedCrack.geo" "$work/"
(cd "$work" && gmsh -2 -format msh41 inclinedCrack.geo -o inclinedCrack.msh >gmsh.log 2>&1) ||
  fail "gmsh failed: $(tail "$work/gmsh.log")"
cmp -s "$work/inclinedCrack.msh" "$src/cases/inclinedCrack/constant/mesh/inclinedCrack.msh" ||
  fail "cases/inclinedCrack/constant/mesh/inclinedCrack.msh differs from what inclinedCrack.geo makes; run its Allmesh"
mkdir "$work/pennyCrack"
cp "$src/cases/pennyCrack/constant/mesh/pennyCrack.geo" "$work/pennyCrack/"
(cd "$work/pennyCrack" && gmsh -3 -format msh41 pennyCrack.geo -o pennyCrack.msh >gmsh.log 2>&1) ||
  fail "gmsh failed: $(tail "$work/pennyCrack/gmsh.log")"
cmp -s "$work/pennyCrack/pennyCrack.msh" "$src/cases/pennyCrack/constant/mesh/pennyCrack.msh" ||
  fail "cases/pennyCrack/constant/mesh/pennyCrack.msh differs from what pennyCrack.geo makes; run its Allmesh"
cp "$src/cases/sneddonCrack/constant/mesh/sneddonCrack.geo" "$work/"
(cd "$work" && gmsh -2 -format msh41 sneddonCrack.geo -o sneddonCrack.msh >gmsh.log 2>&1) ||
  fail "gmsh failed: $(tail "$work/gmsh.log")"
cmp -s "$work/sneddonCrack.msh" "$src/cases/sneddonCrack/constant/mesh/sneddonCrack.msh" ||
  fail "cases/sneddonCrack/constant/mesh/sneddonCrack.msh differs from what sneddonCrack.geo makes; run its Allmesh"
cp "$src/cases/fractureNetwork/constant/mesh/fractureNetwork.geo" "$work/"
(cd "$work" && gmsh -2 -format msh41 fractureNetwork.geo -o fractureNetwork.msh >gmsh.log 2>&1) ||
  fail "gmsh failed: $(tail "$work/gmsh.log")"
cmp -s "$work/fractureNetwork.msh" "$src/cases/fractureNetwork/constant/mesh/fractureNetwork.msh" ||
  fail "cases/fractureNetwork/constant/mesh/fractureNetwork.msh differs from what fractureNetwork.geo makes; run its Allmesh"
# 3D meshes are large: the work folders hold results compared across builds, keep only 2D's.
rm -rf "$work/pennyCrack"
echo "PASS: committed meshes match their generators"
