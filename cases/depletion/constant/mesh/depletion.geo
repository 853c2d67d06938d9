// Mesh of the depletion benchmark (Jansen & Meulenbroek 2022's base case, as GEOS sets it up
// in its validation "stableVerticalFault"): plane strain, the square [-W, W]^2 (x east, y up,
// metres, y = 0 at the reservoir's mid-depth) with a reservoir layer of thickness H offset by a
// vertical fault at x = 0 with throw t: the west compartment spans t/2 - H/2 < y < t/2 + H/2,
// the east compartment -t/2 - H/2 < y < -t/2 + H/2, both out to the sides of the body (a layer
// that is infinite sideways to the fault). The fault runs from y = -Lf to y = Lf, inside the
// body (two tips), and crosses both compartments.
//
//   physical curves    1 "bottom", 2 "right", 3 "top", 4 "left", 5 "fault"
//   physical surfaces  1 "rock", 2 "reservoirWest", 3 "reservoirEast"
//
// The size is h on the fault (and on the layer's edges up to 2 Lf from it) and grows to hFar.
// Usage: gmsh -2 -format msh41 -setnumber h 5 depletion.geo -o depletion.msh

SetFactory("OpenCASCADE");

DefineConstant[
  W    = {2250, Name "Parameters/1Half-width of the body W [m]"},
  H    = {225,  Name "Parameters/2Reservoir thickness H [m]"},
  t    = {75,   Name "Parameters/3Fault throw t [m]"},
  Lf   = {500,  Name "Parameters/4Fault half-length Lf [m]"},
  h    = {10,   Name "Parameters/5Mesh size along the fault h [m]"},
  hFar = {250,  Name "Parameters/6Far-field mesh size [m]"}
];
If (h <= 0 || hFar < h || t >= H || Lf <= (H + t)/2 || Lf >= W)
  Error("need 0 < h <= hFar, t < H and (H + t)/2 < Lf < W");
  Exit;
EndIf

General.NumThreads = 1;
Mesh.RandomSeed = 1;
Mesh.Algorithm = 6;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Rectangle(1) = {-W, -W, 0, 2*W, 2*W};
Rectangle(2) = {-W, t/2 - H/2, 0, W, H};     // the west compartment
Rectangle(3) = {0, -t/2 - H/2, 0, W, H};     // the east compartment
Point(100) = {0, -Lf, 0};
Point(101) = {0, Lf, 0};
Line(100) = {100, 101};
BooleanFragments{ Surface{1}; Delete; }{ Surface{2, 3}; Line{100}; Delete; }

e = 1e-3;
west() = Surface In BoundingBox{-W - e, t/2 - H/2 - e, -e, e, t/2 + H/2 + e, e};
east() = Surface In BoundingBox{-e, -t/2 - H/2 - e, -e, W + e, -t/2 + H/2 + e, e};
all() = Surface{:};
rock() = all();
rock() -= west();
rock() -= east();
If (#west() != 1 || #east() != 1)
  Error("expected one surface per compartment, found %g and %g", #west(), #east());
  Exit;
EndIf
bottom() = Curve In BoundingBox{-W - e, -W - e, -e, W + e, -W + e, e};
top() = Curve In BoundingBox{-W - e, W - e, -e, W + e, W + e, e};
left() = Curve In BoundingBox{-W - e, -W - e, -e, -W + e, W + e, e};
right() = Curve In BoundingBox{W - e, -W - e, -e, W + e, W + e, e};
fault() = Curve In BoundingBox{-e, -Lf - e, -e, e, Lf + e, e};
If (#fault() < 5)
  Error("found %g fault pieces, expected 5 (cut at the compartments' edges)", #fault());
  Exit;
EndIf

// Size: h within 2 h of the fault, growing with the distance to hFar; the compartments' edges
// near the fault (where the stresses concentrate) are inside that zone.
Field[1] = Distance;
Field[1].CurvesList = {fault()};
Field[1].NumPointsPerCurve = 4*Round(2*Lf/h) + 1;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hFar;
Field[2].DistMin = 2*h;
Field[2].DistMax = 2*h + 3*(hFar - h);
Background Field = 2;

Physical Curve("bottom", 1) = {bottom()};
Physical Curve("right", 2) = {right()};
Physical Curve("top", 3) = {top()};
Physical Curve("left", 4) = {left()};
Physical Curve("fault", 5) = {fault()};
Physical Surface("rock", 1) = {rock()};
Physical Surface("reservoirWest", 2) = {west()};
Physical Surface("reservoirEast", 3) = {east()};
