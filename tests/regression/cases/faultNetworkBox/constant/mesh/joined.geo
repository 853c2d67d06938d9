// Mesh of the 3D joined-fault regression test (splitFractureNodes.sh, joinedFaults3d): the unit
// cube with one fault on z = 1/2, x in [0.2, 0.8], made of two rectangles that meet along
// x = 0.5. gmsh -3 -format msh41 -setnumber cut 1 joined.geo -o network.msh: with cut 1 the two
// are the faults 'west' and 'east' (ending together along the line: joined); with cut 0 they
// are one fault 'main'. The geometry, hence the mesh, is the same. across 1: the fault spans
// y in [0, 1], so that the cut line reaches the outer boundary (else y in [0.2, 0.8]).
SetFactory("OpenCASCADE");
DefineConstant[ cut = 1, across = 0, h = 0.2 ];
Mesh.CharacteristicLengthMax = h;
Box(1) = {0, 0, 0, 1, 1, 1};
y0 = across ? 0 : 0.2;
Rectangle(10) = {0.2, y0, 0.5, 0.3, 1 - 2 * y0};
Rectangle(11) = {0.5, y0, 0.5, 0.3, 1 - 2 * y0};
BooleanFragments{ Volume{1}; Delete; }{ Surface{10, 11}; Delete; }
e = 1e-6;
Physical Surface("bottom", 1) = Surface In BoundingBox{-e, -e, -e, 1 + e, 1 + e, e};
Physical Surface("top", 2) = Surface In BoundingBox{-e, -e, 1 - e, 1 + e, 1 + e, 1 + e};
sides[] = Surface In BoundingBox{-e, -e, -e, e, 1 + e, 1 + e};
sides[] += Surface In BoundingBox{1 - e, -e, -e, 1 + e, 1 + e, 1 + e};
sides[] += Surface In BoundingBox{-e, -e, -e, 1 + e, e, 1 + e};
sides[] += Surface In BoundingBox{-e, 1 - e, -e, 1 + e, 1 + e, 1 + e};
Physical Surface("sides", 3) = sides[];
If (cut)
  Physical Surface("west", 5) = Surface In BoundingBox{0.2 - e, -e, 0.5 - e, 0.5 + e, 1 + e, 0.5 + e};
  Physical Surface("east", 6) = Surface In BoundingBox{0.5 - e, -e, 0.5 - e, 0.8 + e, 1 + e, 0.5 + e};
Else
  Physical Surface("main", 5) = Surface In BoundingBox{0.2 - e, -e, 0.5 - e, 0.8 + e, 1 + e, 0.5 + e};
EndIf
Physical Volume("rock", 1) = Volume{:};
