#!/usr/bin/env bash
# Makes the seed corpus of fuzzCase (tests/fuzz/corpus/case/): whole cases, packed in the
# target's input format ("==> path" lines, see fuzzCase.cpp), drawn from the two committed
# cases on very coarse meshes (26 and 31 points) so that every seed runs through the solver
# in milliseconds and the fuzzer starts deep. Between them the seeds reach both mesh readers
# (FreeFEM, gmsh 2.2 and 4.1), P1 and P2, both linear solvers, every optimizer and law, every
# boundary-condition and effect type, tables and value files, and a restart.
#
#   tests/fuzz/makeCaseSeeds.sh BIN_DIR     (BIN_DIR: splitFractureNodes and frictionSolver,
#                                            used for the restart seed's time folder)
# Needs FreeFem++ and gmsh. Rewrites the folder: commit what it makes.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
bin="$(cd "${1:?usage: makeCaseSeeds.sh BIN_DIR}" && pwd)"
out="$here/corpus/case"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export FF_LOADPATH="/usr/lib/freefem++;./" FF_INCLUDEPATH=/usr/include/freefem++/idp

FreeFem++ -nw -ns -v 0 "$repo/cases/paperBenchmark/constant/mesh/square.edp" -n 4 \
  -out "$work/square.msh" >/dev/null
geo="$repo/cases/inclinedCrack/constant/mesh/inclinedCrack.geo"
coarse=(-setnumber a 0.2 -setnumber h 0.1 -setnumber hFar 0.4 -setnumber dMin 0.05 -setnumber dMax 0.3)
gmsh -2 -format msh41 "${coarse[@]}" "$geo" -o "$work/crack41.msh" >/dev/null
gmsh -2 -format msh22 "${coarse[@]}" "$geo" -o "$work/crack22.msh" >/dev/null

# pack FOLDER SEED: pack every file of FOLDER (sorted) into corpus/case/SEED.
pack() {
  local dir=$1 seed=$2
  (cd "$dir" && find . -type f | LC_ALL=C sort | sed 's|^\./||' | while read -r f; do
    printf '==> %s\n' "$f"
    cat "$f"
    [ -z "$(tail -c 1 "$f")" ] || echo  # the next header starts a line
  done) >"$out/$seed"
}

# newCase DIR FROM MESH MESHNAME: copy the dictionaries of cases/FROM and the mesh.
newCase() {
  local dir=$1 from=$2 mesh=$3 name=$4
  mkdir -p "$dir/constant/mesh"
  cp -r "$repo/cases/$from/system" "$repo/cases/$from/0" "$dir/"
  cp "$repo/cases/$from/constant/"*Properties "$dir/constant/"
  cp "$mesh" "$dir/constant/mesh/$name"
  sed -i "s|^mesh .*|mesh        \"constant/mesh/$name\";|" "$dir/system/meshDict"
}

rm -rf "$out"
mkdir -p "$out"

# 1. The paper's benchmark as it is (FreeFEM mesh, λ/μ, Coulomb, Newton, one step).
c="$work/paper"
newCase "$c" paperBenchmark "$work/square.msh" square.msh
pack "$c" paperBenchmark

# 2. Four steps, P2, Eigen's LDLT, plane stress with E/ν, steepest descent, warm start,
#    runTime writes without VTK, a traction and a roller.
c="$work/paperSteps"
newCase "$c" paperBenchmark "$work/square.msh" square.msh
sed -i -e 's/^deltaT .*/deltaT 0.25;/' -e 's/^writeControl .*/writeControl runTime;/' \
  -e 's/^writeInterval .*/writeInterval 0.5;\nwriteVTK no;\ntimePrecision 4;/' "$c/system/controlDict"
sed -i -e 's/^elementOrder .*/elementOrder 2;/' -e 's/^linearSolver .*/linearSolver simplicialLDLT;/' \
  -e 's/type  *semismoothNewton;/type steepestDescent; alphaRelative 0.5;/' \
  -e 's/maxIterations  *100;/maxIterations 40;/' -e 's/warmStart .*/warmStart yes;/' \
  -e 's/gradient .*/gradient frozenRho;/' "$c/system/frictionSolution"
printf 'FoamFile { version 2.0; format ascii; class dictionary; object mechanicalProperties; }\nplaneStress yes;\nE 2.5;\nnu 0.25;\n' \
  >"$c/constant/mechanicalProperties"
sed -i -e 's/left  *{ type free; }/left    { type traction; traction table ((0 (0 0)) (1 (0.01 0))); }/' \
  -e 's/right  *{ type free; }/right   { type fixedDisplacement; components (x); value (0 0); }/' "$c/0/D"
pack "$c" paperSteps

# 3. The inclined crack (gmsh 4.1, two tips, pressure load) with every effect.
c="$work/crack41"
newCase "$c" inclinedCrack "$work/crack41.msh" crack.msh
cat >"$c/constant/effects" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object effects; }
gravity { type bodyForce; density 2500; g (0 -9.81); }
inSitu  { type initialStress; stress (-1e6 -2e6 0); gradient (0 -2.5e4 0); }
pore    { type fracturePressure; fracture crack; pressure table ((0 0) (1 5e5)); }
off     { type bodyForce; active no; density 1; g (0 1); }
EOF
sed -i -e 's/type  *semismoothNewton;/type semismoothNewton; variant krylov;/' "$c/system/frictionSolution"
pack "$c" inclinedCrackEffects

# 4. gmsh 2.2, Tresca, Armijo, a pressure from a values file, two steps.
c="$work/crack22"
newCase "$c" inclinedCrack "$work/crack22.msh" crack.msh
sed -i 's/^deltaT .*/deltaT 0.5;/' "$c/system/controlDict"
printf 'FoamFile { version 2.0; format ascii; class dictionary; object fractureProperties; }\ncrack { law tresca; threshold 1e5; }\n' \
  >"$c/constant/fractureProperties"
sed -i -e 's/type  *semismoothNewton;/type armijo; armijoC 1e-3; maxBacktracks 20;/' \
  -e 's/maxIterations  *100;/maxIterations 30;/' "$c/system/frictionSolution"
printf 'FoamFile { version 2.0; format ascii; class dictionary; object effects; }\npore { type fracturePressure; fracture crack; values "constant/pressure.dat"; }\n' \
  >"$c/constant/effects"
printf '0 1e5\n0.1 2e5\n0.3 1.5e5\n' >"$c/constant/pressure.dat"
pack "$c" inclinedCrackTresca

# 5. A restart: the split mesh and the time folder 0.5 of a run stopped there, continued to 1
#    with startFrom latestTime (coulombCohesion, lbfgs).
c="$work/restart"
newCase "$c" paperBenchmark "$work/square.msh" square.msh
sed -i -e 's/^deltaT .*/deltaT 0.5;/' -e 's/^endTime .*/endTime 0.5;/' -e 's/^writeVTK .*//' "$c/system/controlDict"
echo "writeVTK no;" >>"$c/system/controlDict"
printf 'FoamFile { version 2.0; format ascii; class dictionary; object fractureProperties; }\nfracture { law coulombCohesion; frictionCoefficient 0.3; cohesion 1e-3; }\n' \
  >"$c/constant/fractureProperties"
sed -i -e 's/type  *semismoothNewton;/type lbfgs; memory 4;/' "$c/system/frictionSolution"
"$bin/splitFractureNodes" -case "$c" >/dev/null
"$bin/frictionSolver" -case "$c" >/dev/null
rm -rf "$c/postProcessing" "$c/VTK" "$c/0.5/fractures" "$c/0.5/D" "$c/0.5/solverStatus"
sed -i -e 's/^endTime .*/endTime 1;/' -e 's/^startFrom .*/startFrom latestTime;/' "$c/system/controlDict"
pack "$c" paperRestart

# 6. No fracture (a plain elastic solve), Barzilai-Borwein chosen but never run.
c="$work/noFracture"
newCase "$c" paperBenchmark "$work/square.msh" square.msh
sed -i 's/^fractures .*/fractures ();/' "$c/system/meshDict"
printf 'FoamFile { version 2.0; format ascii; class dictionary; object fractureProperties; }\n' \
  >"$c/constant/fractureProperties"
printf 'FoamFile { version 2.0; format ascii; class pointVectorField; object D; }\nboundaryField {\n bottom { type fixedDisplacement; value (0 0); }\n top { type pressure; pressure 0.1; }\n left { type free; }\n right { type free; }\n fracture { type free; }\n}\n' \
  >"$c/0/D"
sed -i -e 's/type  *semismoothNewton;/type barzilaiBorwein;/' "$c/system/frictionSolution"
pack "$c" noFracture

ls -l "$out"
