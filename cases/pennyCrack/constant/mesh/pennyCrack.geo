// Mesh of the penny-shaped crack benchmark: a disc-shaped fault of radius a centred at the
// origin inside the cube [-L, L]^3 (metres). Untilted, the disc lies in the plane z = 0
// (normal z); the rotation angles rx, ry, rz turn it (and only it: the cube stays) about the
// x, then the y, then the z axis through the origin, so its normal is
// n = Rz(rz) Ry(ry) Rx(rx) (0, 0, 1). A remote stress rotated by the same R
// (sigma' = R sigma R^T) gives the rotated problem (the invariance check).
//
//   physical surfaces  1 "outside" (the six faces of the cube), 5 "fault" (the disc)
//   physical volume    1 "rock"
//
// The disc is cut into the volume by BooleanFragments (OpenCASCADE), so it is a surface of
// mesh triangles inside the tetrahedra, whose nodes the mesh utility later splits; its rim
// is the tip line. The size is h up to dMin from the disc and grows linearly with the
// distance, by slope per metre, up to hFar (a Threshold field on the exact distance to the
// disc, MathEval). The slope matters for accuracy: the volume around the disc carries the
// elastic field, so a convergence study refines it too (a smaller slope), not only h.
//
// The mesh is linear (4-node tetrahedra); P2 is elementOrder 2 in system/frictionSolution
// (the solver adds the mid-edge nodes, so the fault stays the same polygon).
//
// Usage (from this folder; ../../Allmesh does this and writes log.gmsh):
//   gmsh -3 -format msh41 -setnumber h 0.125 pennyCrack.geo -o pennyCrack.msh
// Any parameter below can be set the same way (-setnumber name value).

SetFactory("OpenCASCADE");

DefineConstant[
  a     = {1,    Name "Parameters/1Disc radius a [m]"},
  L     = {4,    Name "Parameters/2Cube half-width L [m]"},
  rx    = {0,    Name "Parameters/3Rotation about x [deg]"},
  ry    = {0,    Name "Parameters/4Rotation about y [deg]"},
  rz    = {0,    Name "Parameters/5Rotation about z [deg]"}
];
DefineConstant[
  h     = {a/8,  Name "Parameters/6Mesh size on the disc h [m]"},
  hFar  = {L/4,  Name "Parameters/7Far-field mesh size [m]"},
  dMin  = {h,    Name "Parameters/8Distance from the disc with size h [m]"},
  slope = {0.25, Name "Parameters/9Size growth per unit distance from the disc"}
];

If (h <= 0 || h > a)
  Error("h = %g: need 0 < h <= a = %g", h, a);
  Exit;   // Exit, not Abort: after Abort gmsh still writes an empty mesh
EndIf
If (slope <= 0 || hFar < h)
  Error("slope = %g, hFar = %g: need slope > 0 and hFar >= h = %g", slope, hFar, h);
  Exit;
EndIf
If (L <= a)
  Error("L = %g: the disc (radius a = %g) must lie inside the cube", L, a);
  Exit;
EndIf

// Reproducible output: one thread and a fixed seed (the defaults in 4.8, stated so that a
// user's options file cannot change the mesh).
General.NumThreads = 1;
Mesh.RandomSeed = 1;
Mesh.Algorithm = 6;              // Frontal-Delaunay (surfaces)
Mesh.Algorithm3D = 1;            // Delaunay

// Sizes come from the field alone.
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Box(1) = {-L, -L, -L, 2*L, 2*L, 2*L};
Disk(100) = {0, 0, 0, a};
Rotate {{1, 0, 0}, {0, 0, 0}, rx*Pi/180} { Surface{100}; }
Rotate {{0, 1, 0}, {0, 0, 0}, ry*Pi/180} { Surface{100}; }
Rotate {{0, 0, 1}, {0, 0, 0}, rz*Pi/180} { Surface{100}; }
BooleanFragments{ Volume{1}; Delete; }{ Surface{100}; Delete; }

// The disc is the only surface inside the sphere of radius a (the cube's faces are at
// distance L > a); every other surface is a face of the cube.
e = 1e-6*a;
disc() = Surface In BoundingBox{-a - e, -a - e, -a - e, a + e, a + e, a + e};
If (#disc() != 1)
  Error("found %g surfaces near the disc, expected 1", #disc());
  Exit;
EndIf
outside() = Surface{:};
outside() -= disc();
If (#outside() != 6)
  Error("found %g outer surfaces, expected the 6 faces of the cube", #outside());
  Exit;
EndIf

// Exact distance to the disc: zeta along n, rho in the plane.
cx = Cos(rx*Pi/180); sx = Sin(rx*Pi/180);
cy = Cos(ry*Pi/180); sy = Sin(ry*Pi/180);
cz = Cos(rz*Pi/180); sz = Sin(rz*Pi/180);
wx = cx*sy; wy = -sx; wz = cx*cy;          // Ry Rx (0, 0, 1)
nx = wx*cz - wy*sz; ny = wx*sz + wy*cz; nz = wz;
Field[1] = MathEval;
zeta = Sprintf("((%.17g)*x + (%.17g)*y + (%.17g)*z)", nx, ny, nz);
rho = StrCat("Sqrt(Abs(x^2 + y^2 + z^2 - ", zeta, "^2))");
Field[1].F = StrCat("Sqrt(", zeta, "^2 + (Abs(", rho, Sprintf(" - (%.17g)) + ", a), rho,
                    Sprintf(" - (%.17g))^2/4)", a));
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = hFar;
Field[2].DistMin = dMin;
Field[2].DistMax = dMin + (hFar - h)/slope;
Background Field = 2;

Physical Surface("outside", 1) = outside();
Physical Surface("fault", 5) = disc();
Physical Volume("rock", 1) = Volume{:};
