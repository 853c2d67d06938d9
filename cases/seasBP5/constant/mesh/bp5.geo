// Mesh of SEAS benchmark BP5-QD (Jiang et al. 2022): a vertical strike-slip fault in a 3D
// half-space, as in tandem's BP5 example (metres, x along strike, y across the fault, z up,
// the free surface at z = 0). The body is the box [-X, X] x [-Y, Y] x [-Z, 0], cut into two
// halves by the fault, the whole plane y = 0: its rectangle |x| <= lf/2, -Wf <= z <= 0 has
// rate-and-state friction, the rest (the benchmark's creeping region) velocity-strengthening
// friction that lets the far sides' motion through (README.md).
//
//   physical surfaces  "top" (z = 0), "bottom" (z = -Z), "plus" (the faces of the y > 0 half
//                      at x = -/+X and y = Y), "minus" (the y < 0 half's), "fault" (the
//                      plane y = 0)
//   physical volume    "rock"
//
// Mesh size: structured on the rectangle, Round(lf/h) x Round(Wf/h) squares cut in two;
// elsewhere h + grading * d with d the distance from the rectangle, at most hFar.
// Usage: gmsh -3 -format msh41 -setnumber h 4000 bp5.geo -o bp5.msh

DefineConstant[
  h       = {4000,   Name "Parameters/1Mesh size on the fault [m]"},
  lf      = {100e3,  Name "Parameters/2Fault length along strike [m]"},
  Wf      = {40e3,   Name "Parameters/3Fault depth [m]"},
  X       = {200e3,  Name "Parameters/4Half-length of the body along strike [m]"},
  Y       = {100e3,  Name "Parameters/5Half-width of the body across the fault [m]"},
  Z       = {100e3,  Name "Parameters/6Depth of the body [m]"},
  grading = {0.3,    Name "Parameters/7Size growth per metre of distance"},
  hFar    = {50e3,   Name "Parameters/8Largest mesh size [m]"}
];

SetFactory("OpenCASCADE");
General.NumThreads = 1;
Mesh.RandomSeed = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
eps = 1;

Box(1) = {-X, -Y, -Z, 2 * X, Y, Z};   // y < 0
Box(2) = {-X, 0, -Z, 2 * X, Y, Z};    // y > 0
// The whole plane y = 0 is the fault (it separates the halves: they move as rigid bodies far
// away); its rectangle |x| <= lf/2, depth <= Wf is meshed apart, structured.
whole = news;
Rectangle(whole) = {-X, -Z, 0, 2 * X, Z};
inner = news;
Rectangle(inner) = {-lf / 2, -Wf, 0, lf, Wf};
Rotate {{1, 0, 0}, {0, 0, 0}, Pi / 2} { Surface{whole, inner}; }   // (x, y, 0) -> (x, 0, y)
v() = BooleanFragments{ Volume{1, 2}; Delete; }{ Surface{whole, inner}; Delete; };

fault() = Surface In BoundingBox{-lf / 2 - eps, -eps, -Wf - eps, lf / 2 + eps, eps, eps};
outer() = Surface In BoundingBox{-X - eps, -eps, -Z - eps, X + eps, eps, eps};
outer() -= fault();
top() = Surface In BoundingBox{-X - eps, -Y - eps, -eps, X + eps, Y + eps, eps};
bottom() = Surface In BoundingBox{-X - eps, -Y - eps, -Z - eps, X + eps, Y + eps, -Z + eps};
// Each half's outer faces: those of its bounding box but the plane y = 0 (the fault and the
// halves' common face), the top and the bottom.
mid() = Surface In BoundingBox{-X - eps, -eps, -Z - eps, X + eps, eps, eps};   // the fault plane
plus() = Surface In BoundingBox{-X - eps, -eps, -Z - eps, X + eps, Y + eps, eps};
minus() = Surface In BoundingBox{-X - eps, -Y - eps, -Z - eps, X + eps, eps, eps};
plus() -= mid();
plus() -= top();
plus() -= bottom();
minus() -= mid();
minus() -= top();
minus() -= bottom();

// The fault: structured, its curves along x with Round(lf/h) segments, along z Round(Wf/h).
faultCurves() = Boundary{ Surface{fault()}; };
For i In {0 : #faultCurves() - 1}
  c = faultCurves(i);
  b() = BoundingBox Curve{c};
  If (Fabs(b(3) - b(0)) > Fabs(b(5) - b(2)))
    Transfinite Curve{c} = Round(lf / h) + 1;
  Else
    Transfinite Curve{c} = Round(Wf / h) + 1;
  EndIf
EndFor
Transfinite Surface{fault()};

Field[1] = Distance;
Field[1].SurfacesList = {fault()};
Field[1].CurvesList = {faultCurves()};
Field[1].NumPointsPerCurve = 2 * Round(lf / h) + 1;
Field[2] = MathEval;
Field[2].F = Sprintf("Min(%g + %g * F1, %g)", h, grading, hFar);
Background Field = 2;

Physical Surface("top", 1) = {top()};
Physical Surface("bottom", 2) = {bottom()};
Physical Surface("plus", 3) = {plus()};
Physical Surface("minus", 4) = {minus()};
Physical Surface("fault", 5) = {fault(), outer()};
Physical Volume("rock", 1) = {v()};
