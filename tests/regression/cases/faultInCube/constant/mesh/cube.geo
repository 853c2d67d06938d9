// Mesh of the 3D regression tests (gmsh -3 -format msh41 cube.geo -o cube.msh): the unit
// cube with the fault square [1/4, 3/4]^2 at z = 1/2 embedded.
lc = 0.12;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
out[] = Extrude {0, 0, 1} { Surface{1}; };
Point(101) = {0.25, 0.25, 0.5, lc}; Point(102) = {0.75, 0.25, 0.5, lc};
Point(103) = {0.75, 0.75, 0.5, lc}; Point(104) = {0.25, 0.75, 0.5, lc};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104}; Plane Surface(101) = {101};
Surface{101} In Volume{out[1]};
Physical Surface("bottom", 1) = {1};
Physical Surface("top", 2) = {out[0]};
Physical Surface("sides", 3) = {out[2], out[3], out[4], out[5]};
Physical Surface("fault", 5) = {101};
Physical Volume("rock", 2) = {out[1]};
