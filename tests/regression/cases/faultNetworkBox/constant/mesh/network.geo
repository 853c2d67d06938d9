// Mesh of the 3D intersection tests (gmsh -3 -format msh41 network.geo -o network.msh): the
// unit cube with three fault surfaces made conforming by OpenCASCADE's boolean fragments:
// 'main' on z = 1/2 (x across, y in [0.2, 0.8]); 'crossing', inclined 60° about the line
// x = 0.45, z = 1/2, through 'main'; 'abutting', on x = 0.75 above 'main', ending on it.
SetFactory("OpenCASCADE");
Mesh.CharacteristicLengthMax = 0.2;
Box(1) = {0, 0, 0, 1, 1, 1};
Rectangle(10) = {0, 0.2, 0.5, 1, 0.6};
Rectangle(11) = {0.2, 0.2, 0.5, 0.5, 0.6};
Rotate {{0, 1, 0}, {0.45, 0, 0.5}, Pi / 3} { Surface{11}; }
Rectangle(12) = {0.75, 0.2, 0.5, 0.3, 0.6};
Rotate {{0, 1, 0}, {0.75, 0, 0.5}, -Pi / 2} { Surface{12}; }
BooleanFragments{ Volume{1}; Delete; }{ Surface{10, 11, 12}; Delete; }
e = 1e-6;
Physical Surface("bottom", 1) = Surface In BoundingBox{-e, -e, -e, 1 + e, 1 + e, e};
Physical Surface("top", 2) = Surface In BoundingBox{-e, -e, 1 - e, 1 + e, 1 + e, 1 + e};
sides[] = Surface In BoundingBox{-e, -e, -e, e, 1 + e, 1 + e};
sides[] += Surface In BoundingBox{1 - e, -e, -e, 1 + e, 1 + e, 1 + e};
sides[] += Surface In BoundingBox{-e, -e, -e, 1 + e, e, 1 + e};
sides[] += Surface In BoundingBox{-e, 1 - e, -e, 1 + e, 1 + e, 1 + e};
Physical Surface("sides", 3) = sides[];
Physical Surface("main", 5) = Surface In BoundingBox{-e, 0.2 - e, 0.5 - e, 1 + e, 0.8 + e, 0.5 + e};
Physical Surface("crossing", 6) = Surface In BoundingBox{0.3, 0.2 - e, 0.28, 0.6, 0.8 + e, 0.72};
Physical Surface("abutting", 7) = Surface In BoundingBox{0.75 - e, 0.2 - e, 0.5 - e, 0.75 + e, 0.8 + e, 0.8 + e};
Physical Volume("rock", 1) = Volume{:};
