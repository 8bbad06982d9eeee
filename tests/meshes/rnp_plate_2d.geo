// rnp_plate_2d.geo -- the 2D elastic plate of specs/000 §4.2 for RNP tests.
//
// Square [0, 1.6]^2, 16 x 16 structured quadrilaterals (h = 0.1; the
// lattice of the paper: 17 x 17 = 289 nodes), all PD.
//
// Regions (material id = tag):    pd (11) everything.
// Boundaries (boundary id = tag): left (1) x = 0, right (2) x = 1.6,
//                                 bottom (3) y = 0, top (4) y = 1.6.

h = 0.1;
L = 1.6;
n = Round(L / h);

Mesh.ElementOrder = 1;

Point(1) = {0, 0, 0};
Point(2) = {L, 0, 0};
Point(3) = {L, L, 0};
Point(4) = {0, L, 0};
Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // right
Line(3) = {3, 4};   // top
Line(4) = {4, 1};   // left
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Transfinite Curve {1, 2, 3, 4} = n + 1;
Transfinite Surface {1};
Recombine Surface {1};

Physical Surface("pd", 11) = {1};
Physical Curve("left", 1)   = {4};
Physical Curve("right", 2)  = {2};
Physical Curve("bottom", 3) = {1};
Physical Curve("top", 4)    = {3};
