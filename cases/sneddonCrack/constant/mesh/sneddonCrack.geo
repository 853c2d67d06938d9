// Sneddon's pressurised crack (2D, plane strain): a straight crack of half-length a on the x
// axis, centred in a square of half-width L = R·a whose sides are held (u = 0), the crack
// faces loaded by a fluid pressure (constant/effects). Far from the crack the displacement
// decays like a²/r, so the held sides cost a relative error of order (a/L)² on the opening
// (measured in README.md).
DefineConstant[
  a    = {1,      Name "Parameters/1Crack half-length a [m]"},
  R    = {50,     Name "Parameters/2Half-width of the square in a [-]"},
  h    = {0.0625, Name "Parameters/3Mesh size along the crack h [m]"},
  hFar = {5,      Name "Parameters/4Far-field mesh size [m]"},
  dMin = {0.25,   Name "Parameters/5Distance from the crack with size h [m]"},
  dMax = {30,     Name "Parameters/6Distance from the crack with size hFar [m]"}
];

If (h <= 0 || h > a)
  Error("h = %g: need 0 < h <= a = %g", h, a);
  Exit;   // Exit, not Abort: after Abort gmsh still writes an empty mesh
EndIf

General.NumThreads = 1;
Mesh.RandomSeed = 1;
Mesh.Algorithm = 6;              // Frontal-Delaunay

Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

L = R*a;
Point(1) = {-L, -L, 0};
Point(2) = { L, -L, 0};
Point(3) = { L,  L, 0};
Point(4) = {-L,  L, 0};
Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // right
Line(3) = {3, 4};   // top
Line(4) = {4, 1};   // left
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Point(5) = {-a, 0, 0};
Point(6) = { a, 0, 0};
Line(5) = {5, 6};
Transfinite Curve{5} = Round(2*a/h) + 1;
Curve{5} In Surface{1};

Field[1] = Distance;
Field[1].CurvesList = {5};
Field[1].PointsList = {5, 6};
Field[1].NumPointsPerCurve = 4*Round(2*a/h) + 1;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hFar;
Field[2].DistMin = dMin;
Field[2].DistMax = dMax;
Background Field = 2;

Physical Curve("outer", 1) = {1, 2, 3, 4};
Physical Curve("crack", 5) = {5};
Physical Surface("body", 1) = {1};
