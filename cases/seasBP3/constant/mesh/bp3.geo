// Mesh of SEAS benchmark BP3-QD (Erickson et al. 2023): a 2D plane-strain half-space cut by a
// planar fault dipping at `dip` degrees from the free surface (y = 0, y up, metres) down to
// the bottom. The body is a parallelogram whose sides are parallel to the fault, as in
// tandem's bp3.geo: the top from (-W, 0) to (W, 0), the bottom at depth D shifted by D cot(dip).
// The fault runs from the trace (0, 0) down-dip; its first Wf metres (down-dip distance
// x_d = depth / sin(dip)) carry rate-and-state friction, the rest (to the bottom) creeps at
// the plate rate.
//
//   physical curves   "top", "bottom", "left", "right", "fault" (0 <= x_d <= Wf),
//                     "creep" (x_d >= Wf)
//   physical surface  "rock" (or, with bimaterial = 1, "hangingWall" and "footWall")
//
// Mesh size: h on the fault's first Wf (Round(Wf/h) equal segments), growing with the distance
// d from it as h + grading * d, at most hFar.
// Usage: gmsh -2 -format msh41 -setnumber h 100 bp3.geo -o bp3.msh

DefineConstant[
  dip     = {60,     Name "Parameters/1Dip [degrees]"},
  h       = {100,    Name "Parameters/2Mesh size along the fault [m]"},
  Wf      = {40e3,   Name "Parameters/3Rate-and-state depth extent, down-dip [m]"},
  D       = {400e3,  Name "Parameters/4Depth of the body [m]"},
  W       = {400e3,  Name "Parameters/5Half-width of the body at the top [m]"},
  grading = {0.1,    Name "Parameters/6Size growth per metre of distance"},
  hFar    = {20e3,   Name "Parameters/7Largest mesh size [m]"}
];

General.NumThreads = 1;
Mesh.RandomSeed = 1;
Mesh.Algorithm = 6;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

c = Cos(dip * Pi / 180);
s = Sin(dip * Pi / 180);
shift = D * c / s;

Point(1) = {0, 0, 0};                  // trace
Point(2) = {Wf * c, -Wf * s, 0};       // end of the rate-and-state part
Point(3) = {shift, -D, 0};             // fault at the bottom
Point(4) = {-W, 0, 0};
Point(5) = {W, 0, 0};
Point(6) = {W + shift, -D, 0};
Point(7) = {-W + shift, -D, 0};

Line(1) = {4, 1};   // top, left of the trace
Line(2) = {1, 5};   // top, right
Line(3) = {5, 6};   // right side
Line(4) = {6, 3};   // bottom, right
Line(5) = {3, 7};   // bottom, left
Line(6) = {7, 4};   // left side
Line(7) = {1, 2};   // fault
Line(8) = {2, 3};   // creep
Transfinite Curve{7} = Round(Wf / h) + 1;

Curve Loop(1) = {7, 8, -4, -3, -2};   // hanging wall (right of the fault), counter-clockwise
Plane Surface(1) = {1};
Curve Loop(2) = {-1, -6, -5, -8, -7};   // footwall (left), counter-clockwise
Plane Surface(2) = {2};

Field[1] = Distance;
Field[1].CurvesList = {7};
Field[1].NumPointsPerCurve = 4 * Round(Wf / h) + 1;
Field[2] = MathEval;
Field[2].F = Sprintf("Min(%g + %g * F1, %g)", h, grading, hFar);
Background Field = 2;

Physical Curve("top", 1) = {1, 2};
Physical Curve("right", 2) = {3};
Physical Curve("bottom", 3) = {4, 5};
Physical Curve("left", 4) = {6};
Physical Curve("fault", 5) = {7};
Physical Curve("creep", 6) = {8};
// With -setnumber bimaterial 1 the two sides are regions of their own ("hangingWall",
// "footWall"; constant/mechanicalProperties' regions), e.g. for rocks of contrasting stiffness.
DefineConstant[ bimaterial = {0, Name "Parameters/8Two regions, one per side of the fault"} ];
If (bimaterial)
  Physical Surface("hangingWall", 1) = {1};
  Physical Surface("footWall", 2) = {2};
Else
  Physical Surface("rock", 1) = {1, 2};
EndIf
