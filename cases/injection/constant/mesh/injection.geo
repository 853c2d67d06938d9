// Mesh of the injection case: a block of layered rock, 2 km x 2 km wide (x east, y north) and
// 1.5 km tall (z up, the top at 1500 m depth: z = -1500, the bottom at z = -3000), cut by a
// planar normal fault that strikes north (along y) and dips 60 degrees to the east.
//
//   layers (physical volumes)  1 "basement" (z < -2500), 2 "reservoir" (-2500 < z < -2000),
//                              3 "caprock" (z > -2000)
//   physical surfaces          1 "bottom", 2 "top", 3 "west", 4 "east", 5 "south",
//                              6 "north" (the outer faces), 10 "fault"
//
// The fault is a rectangle centred at (0, 0, zc): 2 Ls along strike, 2 Ld down dip (its
// vertical extent is 2 Ld sin 60 degrees), entirely inside the block, so its edge is a tip
// line all round. It crosses both layer interfaces; BooleanFragments (OpenCASCADE) makes it a
// surface of mesh triangles inside the tetrahedra (in three pieces, one per layer, joined
// along the interfaces), which splitFractureNodes then splits. Its centre, where the well
// injects, is a mesh node.
//
// The size is h up to dMin from the fault and grows with the distance, by slope per metre, up
// to hFar (a Threshold field on the exact distance to the rectangle, MathEval).
//
// Usage (from this folder; ../../Allmesh does this and writes log.gmsh):
//   gmsh -3 -format msh41 -setnumber h 40 injection.geo -o injection.msh

SetFactory("OpenCASCADE");

DefineConstant[
  W     = {1000,  Name "Parameters/1Half-width of the block W [m]"},
  zTop  = {-1500, Name "Parameters/2Top of the block [m]"},
  zBot  = {-3000, Name "Parameters/3Bottom of the block [m]"},
  z1    = {-2500, Name "Parameters/4Top of the basement [m]"},
  z2    = {-2000, Name "Parameters/5Top of the reservoir [m]"},
  zc    = {-2250, Name "Parameters/6Depth of the fault's centre [m]"},
  Ls    = {700,   Name "Parameters/7Fault half-length along strike Ls [m]"},
  Ld    = {635,   Name "Parameters/8Fault half-width down dip Ld [m]"},
  dip   = {60,    Name "Parameters/9Dip [deg]"}
];
DefineConstant[
  h     = {40,    Name "Parameters/aMesh size on the fault h [m]"},
  hFar  = {250,   Name "Parameters/bFar-field mesh size [m]"},
  dMin  = {h,     Name "Parameters/cDistance from the fault with size h [m]"},
  slope = {0.3,   Name "Parameters/dSize growth per unit distance from the fault"}
];

If (h <= 0 || h > Ld || hFar < h || slope <= 0)
  Error("h = %g, hFar = %g, slope = %g: need 0 < h <= Ld, hFar >= h, slope > 0", h, hFar, slope);
  Exit;   // Exit, not Abort: after Abort gmsh still writes an empty mesh
EndIf
If (!(zBot < z1 && z1 < z2 && z2 < zTop))
  Error("need zBot < z1 < z2 < zTop (the layers from the bottom up)");
  Exit;
EndIf
sd = Sin(dip*Pi/180); cd = Cos(dip*Pi/180);
If (zc - Ld*sd <= zBot || zc + Ld*sd >= zTop || Ld*cd >= W || Ls >= W)
  Error("the fault must lie inside the block");
  Exit;
EndIf

// Reproducible output: one thread and a fixed seed.
General.NumThreads = 1;
Mesh.RandomSeed = 1;
Mesh.Algorithm = 6;              // Frontal-Delaunay (surfaces)
Mesh.Algorithm3D = 1;            // Delaunay
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Box(1) = {-W, -W, zBot, 2*W, 2*W, z1 - zBot};
Box(2) = {-W, -W, z1, 2*W, 2*W, z2 - z1};
Box(3) = {-W, -W, z2, 2*W, 2*W, zTop - z2};
// The fault: made in the plane z = 0 with x down dip, turned about y by the dip (x -> down
// dip: (cos dip, 0, -sin dip)) and moved to its centre.
Rectangle(100) = {-Ld, -Ls, 0, 2*Ld, 2*Ls};
Rotate {{0, 1, 0}, {0, 0, 0}, dip*Pi/180} { Surface{100}; }
Translate {0, 0, zc} { Surface{100}; }
BooleanFragments{ Volume{1, 2, 3}; Delete; }{ Surface{100}; Delete; }

e = 1e-3;
basement() = Volume In BoundingBox{-W - e, -W - e, zBot - e, W + e, W + e, z1 + e};
reservoir() = Volume In BoundingBox{-W - e, -W - e, z1 - e, W + e, W + e, z2 + e};
caprock() = Volume In BoundingBox{-W - e, -W - e, z2 - e, W + e, W + e, zTop + e};
If (#basement() != 1 || #reservoir() != 1 || #caprock() != 1)
  Error("expected one volume per layer, found %g %g %g", #basement(), #reservoir(), #caprock());
  Exit;
EndIf
bottom() = Surface In BoundingBox{-W - e, -W - e, zBot - e, W + e, W + e, zBot + e};
top() = Surface In BoundingBox{-W - e, -W - e, zTop - e, W + e, W + e, zTop + e};
west() = Surface In BoundingBox{-W - e, -W - e, zBot - e, -W + e, W + e, zTop + e};
east() = Surface In BoundingBox{W - e, -W - e, zBot - e, W + e, W + e, zTop + e};
south() = Surface In BoundingBox{-W - e, -W - e, zBot - e, W + e, -W + e, zTop + e};
north() = Surface In BoundingBox{-W - e, W - e, zBot - e, W + e, W + e, zTop + e};
// The fault's pieces: the surfaces inside its bounding box (the interfaces are wider).
fault() = Surface In BoundingBox{-Ld*cd - e, -Ls - e, zc - Ld*sd - e,
                                 Ld*cd + e, Ls + e, zc + Ld*sd + e};
If (#fault() != 3)
  Error("found %g fault pieces, expected 3 (one per layer)", #fault());
  Exit;
EndIf
// The well: a mesh node at the fault's centre, in the reservoir's piece of the fault.
wellPiece() = Surface In BoundingBox{-Ld*cd - e, -Ls - e, z1 - e, Ld*cd + e, Ls + e, z2 + e};
If (zc <= z1 || zc >= z2 || #wellPiece() != 1)
  Error("the fault's centre (the well) must lie in the reservoir (z1 < zc < z2)");
  Exit;
EndIf
Point(1000) = {0, 0, zc};
Point{1000} In Surface{wellPiece(0)};

// Exact distance to the rectangle: w along its normal n = (sin dip, 0, cos dip), u down dip
// d = (cos dip, 0, -sin dip), v along strike (y); max(a, 0) = (a + |a|)/2.
uu = Sprintf("((%.17g)*x - (%.17g)*(z - (%.17g)))", cd, sd, zc);
ww = Sprintf("((%.17g)*x + (%.17g)*(z - (%.17g)))", sd, cd, zc);
du = StrCat("((Abs(", uu, Sprintf(") - %.17g + Abs(Abs(", Ld), uu, Sprintf(") - %.17g))/2)", Ld));
dv = Sprintf("((Abs(y) - %.17g + Abs(Abs(y) - %.17g))/2)", Ls, Ls);
Field[1] = MathEval;
Field[1].F = StrCat("Sqrt(", ww, "^2 + ", du, "^2 + ", dv, "^2)");
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hFar;
Field[2].DistMin = dMin;
Field[2].DistMax = dMin + (hFar - h)/slope;
Background Field = 2;

Physical Surface("bottom", 1) = bottom();
Physical Surface("top", 2) = top();
Physical Surface("west", 3) = west();
Physical Surface("east", 4) = east();
Physical Surface("south", 5) = south();
Physical Surface("north", 6) = north();
Physical Surface("fault", 10) = fault();
Physical Volume("basement", 1) = basement();
Physical Volume("reservoir", 2) = reservoir();
Physical Volume("caprock", 3) = caprock();
