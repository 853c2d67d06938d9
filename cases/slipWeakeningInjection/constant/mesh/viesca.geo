// Mesh of the 2D injection benchmark (Viesca 2021): the square [-W, W]^2 (metres) with a
// straight horizontal fault from (-L, 0) to (L, 0), entirely inside the body (two tips), far
// longer than the ruptures it will carry, so that the body looks infinite to them.
//
//   physical curves   1 "bottom", 2 "right", 3 "top", 4 "left", 5 "fault"
//   physical surface  1 "body"
//
// The fault has Round(2L/h) equal segments; the size grows from h at the fault to hFar.
// Usage: gmsh -2 -format msh41 -setnumber h 0.05 viesca.geo -o viesca.msh

DefineConstant[
  W    = {60,   Name "Parameters/1Half-width of the body W [m]"},
  L    = {15,   Name "Parameters/2Fault half-length L [m]"},
  h    = {0.1,  Name "Parameters/3Mesh size along the fault h [m]"},
  hFar = {6,    Name "Parameters/4Far-field mesh size [m]"}
];

General.NumThreads = 1;
Mesh.RandomSeed = 1;
Mesh.Algorithm = 6;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Point(1) = {-W, -W, 0};
Point(2) = {W, -W, 0};
Point(3) = {W, W, 0};
Point(4) = {-W, W, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Point(5) = {-L, 0, 0};
Point(6) = {L, 0, 0};
Line(5) = {5, 6};
Transfinite Curve{5} = Round(2*L/h) + 1;
Curve{5} In Surface{1};

Field[1] = Distance;
Field[1].CurvesList = {5};
Field[1].NumPointsPerCurve = 4*Round(2*L/h) + 1;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hFar;
Field[2].DistMin = 4*h;
Field[2].DistMax = W/2;
Background Field = 2;

Physical Curve("bottom", 1) = {1};
Physical Curve("right", 2) = {2};
Physical Curve("top", 3) = {3};
Physical Curve("left", 4) = {4};
Physical Curve("fault", 5) = {5};
Physical Surface("body", 1) = {1};
