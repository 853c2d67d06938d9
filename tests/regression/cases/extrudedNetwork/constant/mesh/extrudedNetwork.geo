// Mesh of the extruded-network check (tests/regression/ExtrudedNetworkTest.cpp): a 2D fracture
// network in the square [-5, 5]^2 of the 2D junction tests (tests/regression/cases/junctions),
// extruded in z by layers*h in `layers` layers of prisms, each cut into three tetrahedra.
//
//   "main"     y = 0 from x = -L to L
//   "branch"   through (0, 0) at theta from the x axis, Lb on either side: it crosses main
//   "branch2"  from (xJ2, 0) at -theta2, length Lb2: it ends on main (abutting)
//
// A surface embedded in the volume is not cut into the extruded tetrahedra (gmsh 4.8 cuts the
// prisms without it; tests/regression/cases/extrudedCrack), so the square is cut into pieces
// along the fractures and unlabelled lines that continue each one from its free tips straight
// to the outer boundary: every fracture is then an edge between two pieces, its extrusion a
// face between two volumes, and each layer's nodes are those of the 2D mesh this file makes
// with -setnumber dim 2 (gmsh meshes the base once and copies it per layer). After the
// fragments the pieces of these lines are told apart by slope and extent.
//
//   dim 3: physical surfaces 1 "outer", 5 "main", 7 "branch", 8 "branch2", 9 "back"
//          (z = 0), 10 "front" (z = layers*h); physical volume 1 "rock"
//   dim 2: physical curves 1 "outer", 5 "main", 7 "branch", 8 "branch2"; surface 1 "rock"
//
//   gmsh -3 -format msh41 extrudedNetwork.geo -o extrudedNetwork.msh
//   gmsh -2 -format msh41 -setnumber dim 2 extrudedNetwork.geo -o base.msh
SetFactory("OpenCASCADE");

DefineConstant[
  L      = {1,    Name "Parameters/1Main half-length L [m]"},
  Lb     = {0.8,  Name "Parameters/2Branch half-length Lb [m]"},
  theta  = {120,  Name "Parameters/3Branch angle from the x axis (90 < theta < 180) [deg]"},
  xJ2    = {0.5,  Name "Parameters/4Where branch2 ends on main [m]"},
  Lb2    = {0.6,  Name "Parameters/5Branch2 length [m]"},
  theta2 = {30,   Name "Parameters/6Branch2 angle below the x axis (0 < theta2 < 90) [deg]"},
  h      = {0.1,  Name "Parameters/7Mesh size along the fractures [m]"},
  hFar   = {1,    Name "Parameters/8Mesh size at the outer boundary [m]"},
  dim    = {3,    Name "Parameters/9Dimension (2: the base only)"},
  layers = {2,    Name "Parameters/10Element layers in z"}
];
If (h <= 0 || (dim != 2 && dim != 3) || layers < 1 || theta <= 90 || theta >= 180 ||
    theta2 <= 0 || theta2 >= 90 || xJ2 <= 0 || xJ2 >= L)
  Error("need h > 0, dim 2 or 3, layers >= 1, 90 < theta < 180, 0 < theta2 < 90, 0 < xJ2 < L");
  Exit;
EndIf

General.NumThreads = 1;
Mesh.RandomSeed = 1;
Mesh.Algorithm = 6;
Mesh.MeshSizeExtendFromBoundary = 1;
Mesh.MeshSizeFromCurvature = 0;

c = Cos(theta*Pi/180);   // < 0
s = Sin(theta*Pi/180);
t = s/c;                 // branch's slope dy/dx (< 0)
c2 = Cos(theta2*Pi/180);
s2 = Sin(theta2*Pi/180);
t2 = s2/c2;              // branch2's slope is -t2
x2 = xJ2 + Lb2*c2;       // branch2's free tip
y2 = -Lb2*s2;
If (Fabs(5/t) >= 5 || y2 - (5 - x2)*t2 <= -5)
  Error("the continuations must reach the sides they are meant to (branch: top and bottom; branch2: right)");
  Exit;
EndIf

Rectangle(1) = {-5, -5, 0, 10, 10};
// Points 101-106: the tips; 107-112 where the lines through them reach the sides.
Point(101) = {-L, 0, 0};       Point(107) = {-5, 0, 0};
Point(102) = {L, 0, 0};        Point(108) = {5, 0, 0};
Point(103) = {-Lb*c, -Lb*s, 0}; Point(109) = {-5/t, -5, 0};
Point(104) = {Lb*c, Lb*s, 0};   Point(110) = {5/t, 5, 0};
Point(105) = {xJ2, 0, 0};
Point(106) = {x2, y2, 0};       Point(112) = {5, y2 - (5 - x2)*t2, 0};
Line(101) = {107, 101}; Line(102) = {101, 102}; Line(103) = {102, 108};
Line(104) = {109, 103}; Line(105) = {103, 104}; Line(106) = {104, 110};
Line(107) = {105, 106}; Line(108) = {106, 112};
BooleanFragments{ Surface{1}; Delete; }{ Curve{101:108}; Delete; }
MeshSize{ PointsOf{ Surface{:}; } } = hFar;
// The fractures' tips and junctions (not the continuations' ends on the sides).
near() = Point In BoundingBox{-L - 1e-6, -Lb*s - 1e-6, -1, x2 + 1e-6, Lb*s + 1e-6, 1};
MeshSize{ near() } = h;

If (dim == 3)
  Extrude {0, 0, layers*h} { Surface{:}; Layers{layers}; }
EndIf

// Per piece (a curve in 2D, a vertical face in 3D) from its bounding box in x-y: 5 main,
// 7 branch, 8 branch2, 1 outer (on a side of the square), 0 a continuation.
Macro Classify
  dx = bb(3) - bb(0);
  dy = bb(4) - bb(1);
  e = 1e-6;
  kind = 0;
  If (bb(0) > 5 - e || bb(3) < -5 + e || bb(1) > 5 - e || bb(4) < -5 + e)
    kind = 1;
  ElseIf (dy < e && bb(0) > -L - e && bb(3) < L + e)
    kind = 5;
  ElseIf (Fabs(dy + t*dx) < e && bb(4) < Lb*s + e && bb(1) > -Lb*s - e)
    kind = 7;
  ElseIf (Fabs(dy - t2*dx) < e && bb(0) > xJ2 - e && bb(3) < x2 + e)
    kind = 8;
  EndIf
Return

outer[] = {}; main[] = {}; branch[] = {}; branch2[] = {}; back[] = {}; front[] = {};
If (dim == 2)
  all[] = Curve{:};
Else
  all[] = Surface{:};
EndIf
For i In {0 : #all[] - 1}
  k = all[i];
  If (dim == 2)
    bb() = BoundingBox Curve{k};
  Else
    bb() = BoundingBox Surface{k};
  EndIf
  If (dim == 3 && bb(5) < 1e-6)
    back[] += {k};
  ElseIf (dim == 3 && bb(2) > layers*h - 1e-6)
    front[] += {k};
  Else
    Call Classify;
    If (kind == 1) outer[] += {k}; EndIf
    If (kind == 5) main[] += {k}; EndIf
    If (kind == 7) branch[] += {k}; EndIf
    If (kind == 8) branch2[] += {k}; EndIf
  EndIf
EndFor
If (#main[] != 3 || #branch[] != 2 || #branch2[] != 1)
  Error("expected 3 pieces of main, 2 of branch, 1 of branch2; found %g, %g, %g",
        #main[], #branch[], #branch2[]);
  Exit;
EndIf

If (dim == 2)
  Physical Curve("outer", 1) = {outer[]};
  Physical Curve("main", 5) = {main[]};
  Physical Curve("branch", 7) = {branch[]};
  Physical Curve("branch2", 8) = {branch2[]};
  Physical Surface("rock", 1) = {Surface{:}};
Else
  Physical Surface("outer", 1) = {outer[]};
  Physical Surface("main", 5) = {main[]};
  Physical Surface("branch", 7) = {branch[]};
  Physical Surface("branch2", 8) = {branch2[]};
  Physical Surface("back", 9) = {back[]};
  Physical Surface("front", 10) = {front[]};
  Physical Volume("rock", 1) = {Volume{:}};
EndIf
