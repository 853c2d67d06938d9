// cases/faultNetwork3d: a block 2000 x 2000 x 1500 m (x east, y north, z up, the ground surface
// z = 0) in three layers, with two conjugate normal faults striking north that cross along a
// horizontal line and a bedding fault that ends on one of them. OpenCASCADE's boolean fragments
// make the mesh conform to every surface and to the curves where they meet.
// Parameters (gmsh -setnumber, ./Allmesh -hf 60): hf the mesh size on the faults, hFar away.
SetFactory("OpenCASCADE");
DefineConstant[ hf = 60, hFar = 300 ];
dip = 60 * Pi / 180;
zc = -750;                      // depth of the crossing line (x = 0)
half = 450;                     // the faults' half width down dip [m]
zb = -600;                      // the bedding fault's depth
xb = (zb - zc) / Tan(dip);      // where it meets faultA (x = 86.6 m)

Box(1) = {-1000, -1000, -500, 2000, 2000, 500};      // overburden
Box(2) = {-1000, -1000, -1000, 2000, 2000, 500};     // reservoir
Box(3) = {-1000, -1000, -1500, 2000, 2000, 500};     // basement
// faultA dips 60° to the west (its trace rises to the east), faultB to the east; both
// y in [-600, 600], centred on the crossing line.
Rectangle(100) = {-half, -600, zc, 2 * half, 1200};
Rotate {{0, 1, 0}, {0, 0, zc}, -dip} { Surface{100}; }
Rectangle(101) = {-half, -600, zc, 2 * half, 1200};
Rotate {{0, 1, 0}, {0, 0, zc}, dip} { Surface{101}; }
// The bedding fault: horizontal at zb, from faultA east to x = 700, y in [-400, 400].
Rectangle(102) = {xb, -400, zb, 700 - xb, 800};
BooleanFragments{ Volume{1, 2, 3}; Delete; }{ Surface{100, 101, 102}; Delete; }

e = 1e-3;
Physical Volume("overburden", 1) = Volume In BoundingBox{-1000 - e, -1000 - e, -500 - e, 1000 + e, 1000 + e, e};
Physical Volume("reservoir", 2) = Volume In BoundingBox{-1000 - e, -1000 - e, -1000 - e, 1000 + e, 1000 + e, -500 + e};
Physical Volume("basement", 3) = Volume In BoundingBox{-1000 - e, -1000 - e, -1500 - e, 1000 + e, 1000 + e, -1000 + e};
Physical Surface("top", 1) = Surface In BoundingBox{-1000 - e, -1000 - e, -e, 1000 + e, 1000 + e, e};
Physical Surface("bottom", 2) = Surface In BoundingBox{-1000 - e, -1000 - e, -1500 - e, 1000 + e, 1000 + e, -1500 + e};
Physical Surface("west", 3) = Surface In BoundingBox{-1000 - e, -1000 - e, -1500 - e, -1000 + e, 1000 + e, e};
Physical Surface("east", 4) = Surface In BoundingBox{1000 - e, -1000 - e, -1500 - e, 1000 + e, 1000 + e, e};
Physical Surface("south", 5) = Surface In BoundingBox{-1000 - e, -1000 - e, -1500 - e, 1000 + e, -1000 + e, e};
Physical Surface("north", 6) = Surface In BoundingBox{-1000 - e, 1000 - e, -1500 - e, 1000 + e, 1000 + e, e};
// The faults' pieces (cut by the layer interfaces and by each other): each inside the slab of
// its plane, tested by the bounding box of the piece against the plane.
bedding[] = Surface In BoundingBox{xb - 1, -400 - e, zb - e, 700 + e, 400 + e, zb + e};
faultA[] = {};
faultB[] = {};
all[] = Surface In BoundingBox{-500, -600 - e, -1200, 500, 600 + e, -300};
For k In {0 : #all[] - 1}
  bb[] = BoundingBox Surface{all[k]};
  // a fault piece spans its plane's x and z: x - (z - zc)/tan(dip) = 0 at both corners
  xa = bb[0] - (bb[2] - zc) / Tan(dip); xa2 = bb[3] - (bb[5] - zc) / Tan(dip);
  xbb = bb[0] + (bb[5] - zc) / Tan(dip); xbb2 = bb[3] + (bb[2] - zc) / Tan(dip);
  If (bb[5] - bb[2] > 1)
    If (Fabs(xa) < 1 && Fabs(xa2) < 1)
      faultA[] += all[k];
    EndIf
    If (Fabs(xbb) < 1 && Fabs(xbb2) < 1)
      faultB[] += all[k];
    EndIf
  EndIf
EndFor
Physical Surface("faultA", 7) = faultA[];
Physical Surface("faultB", 8) = faultB[];
Physical Surface("bedding", 9) = bedding[];

// Sizes: hf on the faults, growing to hFar over 600 m.
Field[1] = Distance;
Field[1].SurfacesList = {faultA[], faultB[], bedding[]};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hf;
Field[2].SizeMax = hFar;
Field[2].DistMin = 0;
Field[2].DistMax = 600;
Background Field = 2;
Mesh.CharacteristicLengthFromPoints = 0;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
