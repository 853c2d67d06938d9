// Mesh of the layered-rock regression tests: the unit square [0,1]^2 (metres) in two layers,
// "reservoir" below y = 1/2 and "caprock" above, optionally (crack = 1) cut by a straight crack
// of half-length a at angle theta that crosses the interface at its centre (0.5, 0.5), or
// (crack = 2) by a fracture along the whole interface.
//
//   physical curves   1 "bottom", 2 "right", 3 "top", 4 "left", 5 "crack" (if crack = 1, 2)
//   physical surfaces 1 "reservoir", 2 "caprock"
//
// The crack has 2 Round(a/h) equal segments, half in each layer, so that a node lies on the
// interface. Usage (tests/regression/LayeredRockTest.cpp):
//   gmsh -2 -format msh41 -setnumber crack 1 layeredRock.geo -o layeredRock.msh

DefineConstant[
  crack = {1,    Name "Parameters/1Inclined crack (1), none (0), along the interface (2)"},
  a     = {0.2,  Name "Parameters/2Crack half-length a [m]"},
  theta = {60,   Name "Parameters/3Crack angle from the x axis [deg]"},
  h     = {0.025, Name "Parameters/4Mesh size along the crack h [m]"},
  hFar  = {0.1,  Name "Parameters/5Far-field mesh size [m]"}
];

General.NumThreads = 1;
Mesh.RandomSeed = 1;
Mesh.Algorithm = 6;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromCurvature = 0;

c = Cos(theta*Pi/180);
s = Sin(theta*Pi/180);
Point(1) = {0, 0, 0, hFar};
Point(2) = {1, 0, 0, hFar};
Point(3) = {1, 0.5, 0, hFar};
Point(4) = {1, 1, 0, hFar};
Point(5) = {0, 1, 0, hFar};
Point(6) = {0, 0.5, 0, hFar};
Point(7) = {0.5, 0.5, 0, h};       // the crack's centre, on the interface
Line(1) = {1, 2};                  // bottom
Line(2) = {2, 3};                  // right, reservoir
Line(3) = {3, 4};                  // right, caprock
Line(4) = {4, 5};                  // top
Line(5) = {5, 6};                  // left, caprock
Line(6) = {6, 1};                  // left, reservoir
Line(7) = {3, 7};                  // interface, right half
Line(8) = {7, 6};                  // interface, left half
Curve Loop(1) = {1, 2, 7, 8, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {-7, 3, 4, 5, -8};
Plane Surface(2) = {2};

If (crack == 1)
  Point(8) = {0.5 - a*c, 0.5 - a*s, 0, h};
  Point(9) = {0.5 + a*c, 0.5 + a*s, 0, h};
  Line(9) = {8, 7};
  Line(10) = {7, 9};
  Transfinite Curve{9, 10} = Round(a/h) + 1;
  Curve{9} In Surface{1};
  Curve{10} In Surface{2};
  Physical Curve("crack", 5) = {9, 10};
EndIf
If (crack == 2)
  Transfinite Curve{7, 8} = Round(0.5/h) + 1;
  Physical Curve("crack", 5) = {7, 8};
EndIf

Physical Curve("bottom", 1) = {1};
Physical Curve("right", 2) = {2, 3};
Physical Curve("top", 3) = {4};
Physical Curve("left", 4) = {5, 6};
Physical Surface("reservoir", 1) = {1};
Physical Surface("caprock", 2) = {2};
