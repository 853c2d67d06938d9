// Meshes of the junction tests (tests/regression/JunctionTest.cpp, tests/stability): a square
// [-5, 5]^2 with a main fracture from (-L, 0) to (L, 0) through the junction point (xJ, 0),
// and a branch meeting it there. The test calls gmsh with -setnumber for each variant:
//
//   branch 0   main only
//   branch 1   T: a branch from the junction to (xJ, 0) + Lb (cos theta, sin theta)
//   branch 2   X: a branch through the junction, from -Lb (cos, sin) to +Lb (cos, sin)
//   branch 3   three fractures at one node: the T branch and a second one at -theta
//   cut 1      the main fracture in two fractures, "left" (x < xJ) and "right" (x > xJ)
//   toBoundary 1  the main fracture's right end on the outer boundary (x = 5), the
//                 junction there too when xJ = 5 (branch 1 only)
//   xJ2 != 0   a second junction on the main fracture (xJ < xJ2 < its right end, not with
//              branch 3 or cut 1): "branch2" from (xJ2, 0) to (xJ2, 0) + Lb (cos, -sin)
//
// Physical curves: 1 "outer" (the whole outer boundary), 5 "main" (or 5 "left" and
// 6 "right" with cut 1), 7 "branch", 8 "branch2"; physical surface 1 "rock".
// Reproducible output: one thread and a fixed seed.
//   gmsh -2 -format msh41 -setnumber branch 1 junctions.geo -o junctions.msh

DefineConstant[
  L      = {1,   Name "Parameters/1Main half-length L [m]"},
  Lb     = {0.8, Name "Parameters/2Branch length Lb [m]"},
  theta  = {90,  Name "Parameters/3Branch angle from the x axis [deg]"},
  xJ     = {0,   Name "Parameters/4Junction abscissa [m]"},
  h      = {0.1, Name "Parameters/5Mesh size along the fractures [m]"},
  hFar   = {1,   Name "Parameters/6Mesh size at the outer boundary [m]"},
  branch = {1,   Name "Parameters/7Branch: 0 none, 1 T, 2 X, 3 two branches"},
  cut    = {0,   Name "Parameters/8Main fracture in two (1)"},
  toBoundary = {0, Name "Parameters/9Main fracture to the right side (1)"},
  xJ2    = {0,   Name "Parameters/10Second junction abscissa, 0: none [m]"}
];
If (h <= 0 || L <= 0 || Lb <= 0 || branch < 0 || branch > 3 || xJ <= -L || xJ > (toBoundary ? 5 : L))
  Error("need h, L, Lb > 0, branch 0..3 and the junction on the main fracture");
  Exit;
EndIf
If (xJ2 != 0 && (xJ2 <= xJ || xJ2 >= (toBoundary ? 5 : L) || branch == 3 || cut))
  Error("need xJ < xJ2 < the main fracture's right end, and neither branch 3 nor cut 1");
  Exit;
EndIf

General.NumThreads = 1;
Mesh.RandomSeed = 1;
Mesh.Algorithm = 6;
Mesh.MeshSizeExtendFromBoundary = 1;
Mesh.MeshSizeFromCurvature = 0;

Point(1) = {-5, -5, 0, hFar};
Point(2) = {5, -5, 0, hFar};
Point(3) = {5, 5, 0, hFar};
Point(4) = {-5, 5, 0, hFar};
xR = toBoundary ? 5 : L;
Point(5) = {-L, 0, 0, h};
Point(6) = {xJ, 0, 0, h};
// The main fracture's right end: its own point, or the junction when the junction is there.
pR = 6;
If (xJ < xR)
  Point(7) = {xR, 0, 0, h};
  pR = 7;
EndIf
c = Cos(theta*Pi/180);
s = Sin(theta*Pi/180);
Point(8) = {xJ + Lb*c, Lb*s, 0, h};
If (branch == 2)
  Point(9) = {xJ - Lb*c, -Lb*s, 0, h};
EndIf
If (branch == 3)
  Point(9) = {xJ + Lb*c, -Lb*s, 0, h};
EndIf

If (toBoundary)
  // The right side passes through the main fracture's end (5, 0).
  Line(1) = {1, 2};
  Line(2) = {2, pR};
  Line(3) = {pR, 3};
  Line(4) = {3, 4};
  Line(5) = {4, 1};
  Curve Loop(1) = {1, 2, 3, 4, 5};
  outer[] = {1, 2, 3, 4, 5};
Else
  Line(1) = {1, 2};
  Line(2) = {2, 3};
  Line(3) = {3, 4};
  Line(4) = {4, 1};
  Curve Loop(1) = {1, 2, 3, 4};
  outer[] = {1, 2, 3, 4};
EndIf
Plane Surface(1) = {1};

mainLeft = newl; Line(mainLeft) = {5, 6};
inside[] = {mainLeft};
If (xJ < xR && xJ2 == 0)
  mainRight = newl; Line(mainRight) = {6, 7};
  inside[] += {mainRight};
EndIf
If (xJ2 != 0)
  Point(10) = {xJ2, 0, 0, h};
  Point(11) = {xJ2 + Lb*c, -Lb*s, 0, h};
  mainMiddle = newl; Line(mainMiddle) = {6, 10};
  mainRight = newl; Line(mainRight) = {10, 7};
  b2 = newl; Line(b2) = {10, 11};
  inside[] += {mainMiddle, mainRight, b2};
EndIf
If (branch == 1 || branch == 3)
  b1 = newl; Line(b1) = {6, 8};
  inside[] += {b1};
EndIf
If (branch == 2)
  b1 = newl; Line(b1) = {9, 6};
  b1b = newl; Line(b1b) = {6, 8};
  inside[] += {b1, b1b};
EndIf
If (branch == 3)
  b2 = newl; Line(b2) = {6, 9};
  inside[] += {b2};
EndIf
Curve{inside[]} In Surface{1};

Physical Curve("outer", 1) = {outer[]};
If (cut)
  Physical Curve("left", 5) = {mainLeft};
  If (xJ < xR)
    Physical Curve("right", 6) = {mainRight};
  EndIf
Else
  If (xJ2 != 0)
    Physical Curve("main", 5) = {mainLeft, mainMiddle, mainRight};
  ElseIf (xJ < xR)
    Physical Curve("main", 5) = {mainLeft, mainRight};
  Else
    Physical Curve("main", 5) = {mainLeft};
  EndIf
EndIf
If (branch == 1 || branch == 3)
  Physical Curve("branch", 7) = {b1};
EndIf
If (branch == 2)
  Physical Curve("branch", 7) = {b1, b1b};
EndIf
If (branch == 3 || xJ2 != 0)
  Physical Curve("branch2", 8) = {b2};
EndIf
Physical Surface("rock", 1) = {1};
