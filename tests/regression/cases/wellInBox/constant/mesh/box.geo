// Mesh of the rotation-invariance test (tests/regression/pressureInvariance.sh): the box
// [-1000, 1000]^3 m with a planar fault inside (a rectangle 2 Ls along strike, 2 Ld down dip,
// striking along y and dipping 60 degrees to +x, centred off the origin at (xc, yc, zc), tip
// line all round) and its centre, the well, a mesh node of the fault. Coarse (h on the fault).
//
//   physical surfaces  1 "outer" (the six faces), 10 "fault";  physical volume 1 "rock"
//
// Usage: gmsh -3 -format msh41 box.geo -o box.msh

W = 1000; Ls = 400; Ld = 300; dip = 60*Pi/180;
xc = 100; yc = -50; zc = 80;
h = 70; hFar = 500;

General.NumThreads = 1;
Mesh.RandomSeed = 1;

Point(1) = {-W, -W, -W, hFar}; Point(2) = {W, -W, -W, hFar};
Point(3) = {W, W, -W, hFar};   Point(4) = {-W, W, -W, hFar};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
out[] = Extrude {0, 0, 2*W} { Surface{1}; };

// The fault's corners: centre +- Ls along strike (0, 1, 0) +- Ld down dip (cos, 0, -sin).
dx = Ld*Cos(dip); dz = -Ld*Sin(dip);
Point(101) = {xc - dx, yc - Ls, zc - dz, h}; Point(102) = {xc + dx, yc - Ls, zc + dz, h};
Point(103) = {xc + dx, yc + Ls, zc + dz, h}; Point(104) = {xc - dx, yc + Ls, zc - dz, h};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104}; Plane Surface(101) = {101};
Point(105) = {xc, yc, zc, h};
Point{105} In Surface{101};
Surface{101} In Volume{out[1]};

Physical Surface("outer", 1) = {1, out[0], out[2], out[3], out[4], out[5]};
Physical Surface("fault", 10) = {101};
Physical Volume("rock", 1) = {out[1]};
