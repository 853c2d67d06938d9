// Mesh of cases/fractureNetwork: a vertical section through layered rock, 4 km wide and
// 3 km deep (x to the east, y up, the ground surface at y = 0), with three fractures that
// meet at two junctions:
//   faultA   a normal fault dipping 60 degrees, 2 km long, centred at (2000, -1700), across
//            the reservoir and the caprock into the basement and the overburden;
//   faultB   its conjugate, 1.2 km long, crossing faultA at its centre (an X junction);
//   bedding  a bedding-plane fracture in the caprock at y = -1350, from x = 1000 to
//            faultA: it crosses faultB (a second X junction) and ends on faultA (a T).
// Layers (physical surfaces): basement y < -2000, reservoir -2000 < y < -1500, caprock
// -1500 < y < -1000, overburden above. Physical curves: 1 bottom, 2 right, 3 top, 4 left,
// 5 faultA, 6 faultB, 7 bedding.
//
// OpenCASCADE's BooleanFragments cuts the layers and the fractures at every intersection;
// the pieces are then sorted into physical groups by where they lie.
//   gmsh -2 -format msh41 fractureNetwork.geo -o fractureNetwork.msh     (../../Allmesh)

SetFactory("OpenCASCADE");

DefineConstant[
  hf   = {40,  Name "Parameters/1Mesh size along the fractures [m]"},
  hFar = {300, Name "Parameters/2Mesh size far from them [m]"}
];
If (hf <= 0 || hFar < hf)
  Error("need 0 < hf <= hFar");
  Exit;
EndIf

General.NumThreads = 1;
Mesh.RandomSeed = 1;
Mesh.Algorithm = 6;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

W = 4000; D = 3000;                 // width, depth [m]
yc = -1000; yr = -1500; yb = -2000; // tops of the caprock, the reservoir, the basement
Rectangle(1) = {0, -D, 0, W, D + yb};      // basement
Rectangle(2) = {0, yb, 0, W, yr - yb};     // reservoir
Rectangle(3) = {0, yr, 0, W, yc - yr};     // caprock
Rectangle(4) = {0, yc, 0, W, -yc};         // overburden

xX = 2000; yX = -1700;              // the X junction
ca = 0.5; sa = Sqrt(3)/2;           // cos, sin of 60 degrees
Point(101) = {xX - 1000*ca, yX - 1000*sa, 0};
Point(102) = {xX + 1000*ca, yX + 1000*sa, 0};
Line(101) = {101, 102};             // faultA
Point(103) = {xX + 600*ca, yX - 600*sa, 0};
Point(104) = {xX - 600*ca, yX + 600*sa, 0};
Line(102) = {103, 104};             // faultB
yBed = -1350;
Point(105) = {xX + (yBed - yX)/sa*ca, yBed, 0};   // on faultA
Point(106) = {1000, yBed, 0};
Line(103) = {106, 105};             // bedding

BooleanFragments{ Surface{1:4}; Delete; }{ Curve{101:103}; Delete; }

// Sort the curves by where they lie (their bounding box's corners).
eps = 1e-6;
faultA() = {}; faultB() = {}; bedding() = {};
top() = {}; bottom() = {}; left() = {}; right() = {};
cs() = Curve{:};
For k In {0:#cs()-1}
  c = cs(k);
  bb() = BoundingBox Curve{c};
  x0 = bb(0); y0 = bb(1); x1 = bb(3); y1 = bb(4);
  slope = sa/ca;
  If (x1 - x0 > eps && y1 - y0 > eps &&
      Fabs((y0 - yX) - (x0 - xX)*slope) < 1e-3 && Fabs((y1 - yX) - (x1 - xX)*slope) < 1e-3)
    faultA() += {c};
  ElseIf (x1 - x0 > eps && y1 - y0 > eps &&
          Fabs((y1 - yX) + (x0 - xX)*slope) < 1e-3 && Fabs((y0 - yX) + (x1 - xX)*slope) < 1e-3)
    faultB() += {c};
  ElseIf (Fabs(y0 - yBed) < eps && Fabs(y1 - yBed) < eps)
    bedding() += {c};
  ElseIf (Fabs(y0) < eps && Fabs(y1) < eps)
    top() += {c};
  ElseIf (Fabs(y0 + D) < eps && Fabs(y1 + D) < eps)
    bottom() += {c};
  ElseIf (Fabs(x0) < eps && Fabs(x1) < eps)
    left() += {c};
  ElseIf (Fabs(x0 - W) < eps && Fabs(x1 - W) < eps)
    right() += {c};
  EndIf
EndFor
If (#faultA() != 6 || #faultB() != 5 || #bedding() != 2)
  Error("the fractures were not cut as expected");
  Exit;
EndIf

Physical Curve("bottom", 1) = {bottom()};
Physical Curve("right", 2) = {right()};
Physical Curve("top", 3) = {top()};
Physical Curve("left", 4) = {left()};
Physical Curve("faultA", 5) = {faultA()};
Physical Curve("faultB", 6) = {faultB()};
Physical Curve("bedding", 7) = {bedding()};
Physical Surface("basement", 1) = Surface In BoundingBox{-eps, -D - eps, -eps, W + eps, yb + eps, eps};
Physical Surface("reservoir", 2) = Surface In BoundingBox{-eps, yb - eps, -eps, W + eps, yr + eps, eps};
Physical Surface("caprock", 3) = Surface In BoundingBox{-eps, yr - eps, -eps, W + eps, yc + eps, eps};
Physical Surface("overburden", 4) = Surface In BoundingBox{-eps, yc - eps, -eps, W + eps, eps, eps};

// Sizes: hf within 2 hf of a fracture, growing to hFar 1.5 km away.
Field[1] = Distance;
Field[1].CurvesList = {faultA(), faultB(), bedding()};
Field[1].NumPointsPerCurve = 100;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hf;
Field[2].SizeMax = hFar;
Field[2].DistMin = 2*hf;
Field[2].DistMax = 1500;
Background Field = 2;
