// Mesh of the extruded-2D verification test (tests/regression/Extruded2DTest.cpp): the
// inclined-crack benchmark's square (cases/inclinedCrack: crack of half-length a at theta
// from the x axis, centred in [0,1]^2, sizes from the same Distance + Threshold field)
// extruded in z by `thickness` in `layers` layers of prisms, each prism cut into three
// tetrahedra. gmsh meshes the base surface once and copies it onto every layer, so the
// nodes of each layer are those of the 2D mesh this file makes with -setnumber dim 2.
//
// An embedded curve is not extruded with its surface, and a crack surface extruded apart
// and embedded in the volume does not conform to the tetrahedra (gmsh 4.8 cuts the prisms
// without it). So the square is cut in two surfaces along the crack and two vertical lines
// from its tips to the bottom and top sides: the crack is then a curve of both, its
// extrusion a face of both volumes. The cut lines carry no physical group: they are only
// mesh edges (so the 2D mesh differs from cases/inclinedCrack's by these constrained edges).
//
//   dim 3: physical surfaces 1 "bottom", 2 "right", 3 "top", 4 "left", 5 "crack",
//          6 "back" (z = 0), 7 "front" (z = thickness); physical volume 1 "body"
//   dim 2: physical curves 1 "bottom", 2 "right", 3 "top", 4 "left", 5 "crack";
//          physical surface 1 "body" (the names and numbers of cases/inclinedCrack)
//
// Usage (from this folder; ../../Allmesh does this):
//   gmsh -3 -format msh41 extrudedCrack.geo -o extrudedCrack.msh
//   gmsh -2 -format msh41 -setnumber dim 2 extrudedCrack.geo -o base.msh

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
DefineConstant[
  dim       = {3,        Name "Parameters/7Dimension of the mesh (2: the base only)"},
  layers    = {2,        Name "Parameters/8Element layers in z"},
  thickness = {layers*h, Name "Parameters/9Thickness in z [m]"}
];

If (h <= 0 || h > a || (dim != 2 && dim != 3) || layers < 1 || thickness <= 0)
  Error("need 0 < h <= a, dim 2 or 3, layers >= 1, thickness > 0");
  Exit;   // Exit, not Abort: after Abort gmsh still writes an empty mesh
EndIf

// Reproducible output: one thread and a fixed seed (as cases/inclinedCrack).
General.NumThreads = 1;
Mesh.RandomSeed = 1;
Mesh.Algorithm = 6;              // Frontal-Delaunay
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

c = Cos(theta*Pi/180);
s = Sin(theta*Pi/180);
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Point(5) = {0.5 - a*c, 0.5 - a*s, 0};   // lower tip
Point(6) = {0.5 + a*c, 0.5 + a*s, 0};   // upper tip
Point(7) = {0.5 - a*c, 0, 0};           // below the lower tip
Point(8) = {0.5 + a*c, 1, 0};           // above the upper tip
Line(1) = {1, 7};   // bottom, left of the cut
Line(2) = {7, 2};   // bottom, right of the cut
Line(3) = {2, 3};   // right
Line(4) = {3, 8};   // top, right of the cut
Line(5) = {8, 4};   // top, left of the cut
Line(6) = {4, 1};   // left
Line(7) = {7, 5};   // cut below the crack
Line(8) = {5, 6};   // the crack, from the lower tip to the upper one
Line(9) = {6, 8};   // cut above the crack
Transfinite Curve{8} = Round(2*a/h) + 1;
// Counter-clockwise, so that the triangles are.
Curve Loop(1) = {1, 7, 8, 9, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -9, -8, -7};
Plane Surface(2) = {2};

Field[1] = Distance;
Field[1].CurvesList = {8};
Field[1].PointsList = {5, 6};
Field[1].NumPointsPerCurve = 4*Round(2*a/h) + 1;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hFar;
Field[2].DistMin = dMin;
Field[2].DistMax = dMax;
Background Field = 2;

If (dim == 2)
  Physical Curve("bottom", 1) = {1, 2};
  Physical Curve("right", 2) = {3};
  Physical Curve("top", 3) = {4, 5};
  Physical Curve("left", 4) = {6};
  Physical Curve("crack", 5) = {8};
  Physical Surface("body", 1) = {1, 2};
Else
  // Extrude returns the top face, the volume, then one face per curve of the loop in order.
  l[] = Extrude {0, 0, thickness} { Surface{1}; Layers{layers}; };
  r[] = Extrude {0, 0, thickness} { Surface{2}; Layers{layers}; };
  Physical Surface("bottom", 1) = {l[2], r[2]};
  Physical Surface("right", 2) = {r[3]};
  Physical Surface("top", 3) = {r[4], l[6]};
  Physical Surface("left", 4) = {l[7]};
  Physical Surface("crack", 5) = {l[4]};
  Physical Surface("back", 6) = {1, 2};
  Physical Surface("front", 7) = {l[0], r[0]};
  Physical Volume("body", 1) = {l[1], r[1]};
EndIf
