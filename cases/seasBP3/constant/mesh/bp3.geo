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
//   physical surface  "rock" (or, with bimaterial = 1, "hangingWall" and "footWall"; with
//                     layer = L > 0, "upper" and "lower" of a horizontal interface at depth L)
//
// Mesh size: h on the fault's first Wf (Round(Wf/h) equal segments), growing with the distance
// d from it as h + grading * d, at most hFar.
//
// The body stands for the half-space: its sides, held at the rigid motion, take the place of
// the far field, where an event's displacement decays only as 1/distance in 2D. With tandem's
// 400 km (the default) an event's surface offsets near the fault are shifted by a few cm (0.04
// m down at 16 km for a 3.4 m event of the 30-degree normal case) against the boundary-element
// code FDRA; with D = W = 6400e3 and hFar = 150e3 they are FDRA's to 3 mm
// (cases/seasBP3/README.md). Give such a body `inner` = 100e3 (below): meshed whole, its
// surfaces along the fault got flat triangles of three fault nodes at h = 25 m
// (splitFractureNodes refuses them, naming the element).
// Usage: gmsh -2 -format msh41 -setnumber h 100 bp3.geo -o bp3.msh

DefineConstant[
  dip     = {60,     Name "Parameters/1Dip [degrees]"},
  h       = {100,    Name "Parameters/2Mesh size along the fault [m]"},
  Wf      = {40e3,   Name "Parameters/3Rate-and-state depth extent, down-dip [m]"},
  D       = {400e3,  Name "Parameters/4Depth of the body [m]"},
  W       = {400e3,  Name "Parameters/5Half-width of the body at the top [m]"},
  grading = {0.1,    Name "Parameters/6Size growth per metre of distance"},
  hFar    = {20e3,   Name "Parameters/7Largest mesh size [m]"},
  layer   = {0,      Name "Parameters/9Depth of a horizontal layer interface [m] (0: none)"},
  inner   = {0,      Name "Parameters/10Half-width and depth of a near-fault region [m] (0: none)"}
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

If (inner > 0 && layer > 0)
  Error("bp3.geo: 'inner' and 'layer' cannot be combined yet");
  Abort;
EndIf
If (inner > 0 && (inner >= W || inner >= D || inner <= Wf * s))
  Error("bp3.geo: 'inner' must be deeper than the rate-and-state part (Wf sin(dip)) and less than W and D");
  Abort;
EndIf

If (layer <= 0 && inner > 0)
// A near-fault region, a parallelogram like the body's, `inner` wide on each side of the trace
// and `inner` deep, holds the fault's rate-and-state part: the surfaces along the fault are
// meshed in its bounding box. In a body of thousands of km meshed whole, Frontal-Delaunay left
// triangles of three collinear fault nodes at h = 25 m (at 6 400 km, dip 30 and 60).
si = inner * c / s;
Point(8) = {si, -inner, 0};             // the fault at the region's bottom
Point(9) = {-inner, 0, 0};
Point(10) = {inner, 0, 0};
Point(11) = {inner + si, -inner, 0};
Point(12) = {-inner + si, -inner, 0};
Line(1) = {4, 9};   Line(21) = {9, 1};    // top, left of the trace
Line(2) = {10, 5};  Line(22) = {1, 10};   // top, right
Line(3) = {5, 6};   // right side
Line(4) = {6, 3};   // bottom, right
Line(5) = {3, 7};   // bottom, left
Line(6) = {7, 4};   // left side
Line(7) = {1, 2};   // fault
Line(8) = {2, 8};   // creep, inside the region
Line(9) = {8, 3};   // creep, outside
Line(23) = {8, 11}; Line(24) = {11, 10};  // the region's bottom and side, right
Line(25) = {8, 12}; Line(26) = {12, 9};   // the region's bottom and side, left
Transfinite Curve{7} = Round(Wf / h) + 1;
Curve Loop(1) = {7, 8, 23, 24, -22};        // hanging wall, near the fault
Plane Surface(1) = {1};
Curve Loop(2) = {-21, -26, -25, -8, -7};    // footwall, near the fault
Plane Surface(2) = {2};
Curve Loop(3) = {-24, -23, 9, -4, -3, -2};  // hanging wall, beyond
Plane Surface(3) = {3};
Curve Loop(4) = {-1, -6, -5, -9, 25, 26};   // footwall, beyond
Plane Surface(4) = {4};
faultCurves[] = {7};
topCurves[] = {1, 21, 22, 2};
creepCurves[] = {8, 9};
leftCurves[] = {6};
rightCurves[] = {3};
hangingWall[] = {1, 3};
footWall[] = {2, 4};
ElseIf (layer <= 0)
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
faultCurves[] = {7};
topCurves[] = {1, 2};
creepCurves[] = {8};
leftCurves[] = {6};
rightCurves[] = {3};
hangingWall[] = {1};
footWall[] = {2};
Else
// A horizontal interface at depth `layer` (above the end of the rate-and-state part) splits
// both sides: regions "upper" and "lower".
lc = layer * c / s;
Point(8) = {lc, -layer, 0};            // the fault at the interface
Point(9) = {-W + lc, -layer, 0};       // left side
Point(10) = {W + lc, -layer, 0};       // right side
Line(1) = {4, 1};
Line(2) = {1, 5};
Line(3) = {5, 10};
Line(13) = {10, 6};
Line(4) = {6, 3};
Line(5) = {3, 7};
Line(6) = {7, 9};
Line(12) = {9, 4};
Line(7) = {1, 8};    // fault above the interface
Line(11) = {8, 2};   // fault below it
Line(8) = {2, 3};    // creep
Line(14) = {9, 8};   // interface, footwall
Line(15) = {8, 10};  // interface, hanging wall
Transfinite Curve{7} = Round(layer / s / h) + 1;
Transfinite Curve{11} = Round((Wf - layer / s) / h) + 1;
Curve Loop(1) = {7, 15, -3, -2};           // hanging wall, upper
Plane Surface(1) = {1};
Curve Loop(3) = {11, 8, -4, -13, -15};     // hanging wall, lower
Plane Surface(3) = {3};
Curve Loop(2) = {-1, -12, 14, -7};         // footwall, upper
Plane Surface(2) = {2};
Curve Loop(4) = {-6, -5, -8, -11, -14};    // footwall, lower
Plane Surface(4) = {4};
faultCurves[] = {7, 11};
topCurves[] = {1, 2};
creepCurves[] = {8};
leftCurves[] = {6, 12};
rightCurves[] = {3, 13};
hangingWall[] = {1};
footWall[] = {2};
EndIf

Field[1] = Distance;
Field[1].CurvesList = {faultCurves[]};
Field[1].NumPointsPerCurve = 4 * Round(Wf / h) + 1;
Field[2] = MathEval;
Field[2].F = Sprintf("Min(%g + %g * F1, %g)", h, grading, hFar);
Background Field = 2;

Physical Curve("top", 1) = {topCurves[]};
Physical Curve("right", 2) = {rightCurves[]};
Physical Curve("bottom", 3) = {4, 5};
Physical Curve("left", 4) = {leftCurves[]};
Physical Curve("fault", 5) = {faultCurves[]};
Physical Curve("creep", 6) = {creepCurves[]};
// With -setnumber bimaterial 1 the two sides are regions of their own ("hangingWall",
// "footWall"; constant/mechanicalProperties' regions), e.g. for rocks of contrasting stiffness;
// with -setnumber layer L (> 0) the rock above depth L and below it are ("upper", "lower").
DefineConstant[ bimaterial = {0, Name "Parameters/8Two regions, one per side of the fault"} ];
If (layer > 0)
  Physical Surface("upper", 1) = {1, 2};
  Physical Surface("lower", 2) = {3, 4};
ElseIf (bimaterial)
  Physical Surface("hangingWall", 1) = {hangingWall[]};
  Physical Surface("footWall", 2) = {footWall[]};
Else
  Physical Surface("rock", 1) = {hangingWall[], footWall[]};
EndIf
