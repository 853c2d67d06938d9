# Sourced by tests/regression/quasiDynamic.sh and utilities/frictionStudy/rateStateStudy.sh:
# rateStateBlock SOURCE_DIR DEST A B L V_INIT LOAD_END LOAD_X END_TIME DELTA_T
# makes DEST, a rate-and-state case on cases/paperBenchmark's mesh (a unit square cut across
# its width by a horizontal fault, so the upper block can slide): E = 30 GPa, ν = 0.25, an
# in-situ stress σ_n = −10 MPa, τ = 5.5 MPa; law rateState with a, b, L (characteristicSlip
# [m]), f₀ = 0.6, V₀ = 1e-5 m/s, initialSlipRate V_INIT [m/s], c_s = 3464 m/s; the top moved
# sideways by LOAD_X [m] at LOAD_END [s] (linearly from 0); timeIntegration quasiDynamic at
# relativeTolerance 1e-8; endTime END_TIME, deltaT DELTA_T; split. Exits 1 if the paperBenchmark
# files it edits changed.
rateStateBlock() {
  local src=$1 dest=$2 a=$3 b=$4 L=$5 vinit=$6 loadEnd=$7 loadX=$8 endTime=$9 deltaT=${10}
  rm -rf "$dest"
  cp -r "$src/cases/paperBenchmark" "$dest"
  (
    cd "$dest"
    rm -rf [1-9]* VTK postProcessing log.* constant/splitMesh
    cat >constant/mechanicalProperties <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object mechanicalProperties; }
E 30e9;
nu 0.25;
DICT
    cat >constant/effects <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object effects; }
inSitu { type initialStress; stress (-10e6 -10e6 5.5e6); }
DICT
    cat >constant/fractureProperties <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object fractureProperties; }
fracture
{
    law rateState; a $a; b $b; characteristicSlip $L; referenceFriction 0.6;
    referenceSlipRate 1e-5; initialSlipRate $vinit; shearWaveSpeed 3464;
}
DICT
    cat >system/frictionSolution <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object frictionSolution; }
elementOrder    1;
timeIntegration { type quasiDynamic; relativeTolerance 1e-8; }
control { gammaRelative 1; optimizer { type semismoothNewton; tolerance 1e-10; maxIterations 100; } }
DICT
    sed -i "s/value   table ((0 (0 0)) (1 (-0.02 -0.025)));/value table ((0 (0 0)) ($loadEnd ($loadX 0)));/" 0/D
    grep -q "($loadEnd ($loadX 0))" 0/D || { echo "rateStateBlock: paperBenchmark's 0/D changed" >&2; exit 1; }
    sed -i "s/^endTime .*/endTime $endTime;/; s/^deltaT .*/deltaT $deltaT;/" system/controlDict
    grep -q "^endTime $endTime;" system/controlDict || { echo "rateStateBlock: paperBenchmark's controlDict changed" >&2; exit 1; }
    "$bin/splitFractureNodes" -case . >log.splitFractureNodes 2>&1
  )
}
