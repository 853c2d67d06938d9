// Mesh of the shallow-intersection stability check (splitFractureNodes.sh shallowIntersection3d):
// the unit cube with 'main' on z = 1/2 and 'shallow' through it at 10° (rotated about the line
// x = 1/2, z = 1/2), conforming by OpenCASCADE's boolean fragments; -setnumber angle changes it.
SetFactory("OpenCASCADE");
DefineConstant[ angle = 10, h = 0.1 ];
Mesh.CharacteristicLengthMax = h;
Box(1) = {0, 0, 0, 1, 1, 1};
Rectangle(10) = {0.1, 0.2, 0.5, 0.8, 0.6};
Rectangle(11) = {0.15, 0.2, 0.5, 0.7, 0.6};
Rotate {{0, 1, 0}, {0.5, 0, 0.5}, angle * Pi / 180} { Surface{11}; }
BooleanFragments{ Volume{1}; Delete; }{ Surface{10, 11}; Delete; }
e = 1e-6;
Physical Surface("bottom", 1) = Surface In BoundingBox{-e, -e, -e, 1 + e, 1 + e, e};
Physical Surface("top", 2) = Surface In BoundingBox{-e, -e, 1 - e, 1 + e, 1 + e, 1 + e};
sides[] = Surface In BoundingBox{-e, -e, -e, e, 1 + e, 1 + e};
sides[] += Surface In BoundingBox{1 - e, -e, -e, 1 + e, 1 + e, 1 + e};
sides[] += Surface In BoundingBox{-e, -e, -e, 1 + e, e, 1 + e};
sides[] += Surface In BoundingBox{-e, 1 - e, -e, 1 + e, 1 + e, 1 + e};
Physical Surface("sides", 3) = sides[];
main[] = Surface In BoundingBox{0.1 - e, 0.2 - e, 0.5 - e, 0.9 + e, 0.8 + e, 0.5 + e};
shallow[] = Surface In BoundingBox{0.1, 0.2 - e, 0.43, 0.9, 0.8 + e, 0.57};
shallow[] -= main[];
Physical Surface("main", 5) = main[];
Physical Surface("shallow", 6) = shallow[];
Physical Volume("rock", 1) = Volume{:};
