// mixed_mode_plate.geo -- the plate of mixed_mode_plate.prm: a mostly
// peridynamic mesh for mixed-mode crack growth (issue 21).
//
// Square [-0.5, 0.5]^2 in a structured n x n grid of quadrilaterals
// (h = 1 / n). The vertical band |x| <= n_pd h / 2 (n_pd columns, full
// height) is peridynamic, the two side strips finite elements: with
// n = 75, n_pd = 47 the PD cells are 62.7 % of the mesh (11 552 DoFs),
// with n_pd = 61 they are 81.3 %. n - n_pd must be even.
//
// Regions (material id = tag):    pd (11) the band, fe (12) the sides.
// Boundaries (boundary id = tag): left (1), right (2), bottom (3), top (4).

n    = 75;
n_pd = 47;
L    = 0.5;
h    = 2 * L / n;
b    = n_pd * h / 2;

Mesh.ElementOrder = 1;

Point(1) = {-L, -L, 0};
Point(2) = {-b, -L, 0};
Point(3) = { b, -L, 0};
Point(4) = { L, -L, 0};
Point(5) = {-L,  L, 0};
Point(6) = {-b,  L, 0};
Point(7) = { b,  L, 0};
Point(8) = { L,  L, 0};

Line(1)  = {1, 2};
Line(2)  = {2, 3};
Line(3)  = {3, 4};
Line(4)  = {5, 6};
Line(5)  = {6, 7};
Line(6)  = {7, 8};
Line(7)  = {1, 5};
Line(8)  = {2, 6};
Line(9)  = {3, 7};
Line(10) = {4, 8};

Curve Loop(1) = {1, 8, -4, -7};
Curve Loop(2) = {2, 9, -5, -8};
Curve Loop(3) = {3, 10, -6, -9};
Plane Surface(1) = {1};   // FE, left
Plane Surface(2) = {2};   // PD band
Plane Surface(3) = {3};   // FE, right

Transfinite Curve {1, 3, 4, 6}  = (n - n_pd) / 2 + 1;
Transfinite Curve {2, 5}        = n_pd + 1;
Transfinite Curve {7, 8, 9, 10} = n + 1;
Transfinite Surface {1, 2, 3};
Recombine Surface {1, 2, 3};

Physical Surface("pd", 11) = {2};
Physical Surface("fe", 12) = {1, 3};
Physical Curve("left", 1)   = {7};
Physical Curve("right", 2)  = {10};
Physical Curve("bottom", 3) = {1, 2, 3};
Physical Curve("top", 4)    = {4, 5, 6};
