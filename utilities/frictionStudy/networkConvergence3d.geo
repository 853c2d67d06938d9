// Mesh of the 3D intersection convergence study (networkConvergence3d.sh): the unit cube of
// tests/regression/cases/faultNetworkBox with its two crossing faults, made conforming by
// OpenCASCADE's boolean fragments: 'main' on z = 1/2 (x across, y in [0.2, 0.8]) and
// 'crossing', inclined 60° about the line x = 0.45, z = 1/2, through 'main'. They cross along
// x = 0.45, z = 1/2, y in [0.2, 0.8]. Size h on the faults, growing to hFar away from them.
//   gmsh -3 -format msh41 -setnumber h 0.05 networkConvergence3d.geo -o network.msh
SetFactory("OpenCASCADE");
DefineConstant[
  h    = {0.05, Name "Parameters/1Mesh size on the faults [m]"},
  hFar = {0.2,  Name "Parameters/2Mesh size away from them [m]"}
];
General.NumThreads = 1;
Mesh.RandomSeed = 1;
Box(1) = {0, 0, 0, 1, 1, 1};
Rectangle(10) = {0, 0.2, 0.5, 1, 0.6};
Rectangle(11) = {0.2, 0.2, 0.5, 0.5, 0.6};
Rotate {{0, 1, 0}, {0.45, 0, 0.5}, Pi / 3} { Surface{11}; }
BooleanFragments{ Volume{1}; Delete; }{ Surface{10, 11}; Delete; }
e = 1e-6;
main[] = Surface In BoundingBox{-e, 0.2 - e, 0.5 - e, 1 + e, 0.8 + e, 0.5 + e};
crossing[] = Surface In BoundingBox{0.3, 0.2 - e, 0.28, 0.6, 0.8 + e, 0.72};
Physical Surface("bottom", 1) = Surface In BoundingBox{-e, -e, -e, 1 + e, 1 + e, e};
Physical Surface("top", 2) = Surface In BoundingBox{-e, -e, 1 - e, 1 + e, 1 + e, 1 + e};
sides[] = Surface In BoundingBox{-e, -e, -e, e, 1 + e, 1 + e};
sides[] += Surface In BoundingBox{1 - e, -e, -e, 1 + e, 1 + e, 1 + e};
sides[] += Surface In BoundingBox{-e, -e, -e, 1 + e, e, 1 + e};
sides[] += Surface In BoundingBox{-e, 1 - e, -e, 1 + e, 1 + e, 1 + e};
Physical Surface("sides", 3) = sides[];
Physical Surface("main", 5) = main[];
Physical Surface("crossing", 6) = crossing[];
Physical Volume("rock", 1) = Volume{:};

Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Field[1] = Distance;
Field[1].SurfacesList = {main[], crossing[]};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hFar;
Field[2].DistMin = 0.02;
Field[2].DistMax = 0.3;
Background Field = 2;
