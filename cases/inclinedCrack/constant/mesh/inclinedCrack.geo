// Mesh of the inclined-crack benchmark: the unit square [0,1]^2 (metres) with a straight
// crack of half-length a centred at (0.5, 0.5), at angle theta from the x axis, entirely
// inside the body (two tips). The crack is embedded in the surface, so it is a line of
// mesh edges whose nodes the mesh utility later splits.
//
//   physical curves   1 "bottom", 2 "right", 3 "top", 4 "left", 5 "crack"
//   physical surface  1 "body"
//
// The crack has Round(2a/h) equal segments (so node count and spacing are exact); the size
// grows from h at the crack to hFar in the far field (Distance + Threshold fields).
//
// Usage (from this folder; ../../Allmesh does this and writes log.gmsh):
//   gmsh -2 -format msh41 -setnumber h 0.003125 inclinedCrack.geo -o inclinedCrack.msh
// Any parameter below can be set the same way (-setnumber name value).

DefineConstant[
  a     = {0.05, Name "Parameters/1Crack half-length a [m]"},
  theta = {60,   Name "Parameters/2Crack angle from the x axis [deg]"}
];
DefineConstant[
  h     = {a/16, Name "Parameters/3Mesh size along the crack h [m]"},
  hFar  = {0.1,  Name "Parameters/4Far-field mesh size [m]"},
  dMin  = {a/4,  Name "Parameters/5Distance from the crack with size h [m]"},
  dMax  = {0.4,  Name "Parameters/6Distance from the crack with size hFar [m]"}
];

If (h <= 0 || h > a)
  Error("h = %g: need 0 < h <= a = %g", h, a);
  Exit;   // Exit, not Abort: after Abort gmsh still writes an empty mesh
EndIf

// Reproducible output: one thread and a fixed seed (the defaults in 4.8, stated so that a
// user's options file cannot change the mesh).
General.NumThreads = 1;
Mesh.RandomSeed = 1;
Mesh.Algorithm = 6;              // Frontal-Delaunay

// Sizes come from the field alone.
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

// Outer square, counter-clockwise so that the triangles are too.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // right
Line(3) = {3, 4};   // top
Line(4) = {4, 1};   // left
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// The crack, from the lower tip to the upper one.
c = Cos(theta*Pi/180);
s = Sin(theta*Pi/180);
Point(5) = {0.5 - a*c, 0.5 - a*s, 0};
Point(6) = {0.5 + a*c, 0.5 + a*s, 0};
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

Physical Curve("bottom", 1) = {1};
Physical Curve("right", 2) = {2};
Physical Curve("top", 3) = {3};
Physical Curve("left", 4) = {4};
Physical Curve("crack", 5) = {5};
Physical Surface("body", 1) = {1};
