// lps_fft_square.geo -- the unit square [0, 1]^2 as one transfinite block of equal square cells (a
// uniform grid for Peridynamics/Model = lps fft), its cell count following pdfem's
// `Mesh/Mesh size factor` (gmsh -clscale): n = Round(16 / factor) cells per side, so factor 1 gives
// 16 x 16 cells (289 nodes), and factor 0.0627451 (16 / 255) 255 x 255 cells, 2^16 nodes.
//
// Regions (material id = tag):    plate (11).
// Boundaries (boundary id = tag): left (1) x = 0, bottom (2) y = 0, right (3) x = 1, top (4) y = 1.

n = Round(16 / Mesh.MeshSizeFactor);   // cells per side

Mesh.ElementOrder = 1;

Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};

Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // right
Line(3) = {3, 4};   // top
Line(4) = {4, 1};   // left

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Transfinite Curve {1:4} = n + 1;
Transfinite Surface {1};
Recombine Surface {1};

Physical Surface("plate", 11) = {1};

Physical Curve("left", 1)   = {4};
Physical Curve("bottom", 2) = {1};
Physical Curve("right", 3)  = {2};
Physical Curve("top", 4)    = {3};
