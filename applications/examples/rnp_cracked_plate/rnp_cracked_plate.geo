// rnp_cracked_plate.geo -- the pre-cracked plate of specs/000 §4.5-4.6 at the paper's resolution.
//
// Plate [0, 15] x [0, 15] with the layers D^-eps (y in [-1.6, 0]) and D^+eps (y in [15, 16.6]) of
// the hard-loading example: [0, 15] x [-1.6, 16.6], h = 0.2: 76 x 92 = 6992 nodes, no node row on
// the pre-crack line y = 7.5 (given in the scene). All PD.
//
// Boundaries (boundary id = tag): left (1), right (2), bottom (3) y = -1.6, top (4) y = 16.6.

h  = 0.2;
L  = 15;
y0 = -1.6;
y1 = 16.6;

Mesh.ElementOrder = 1;

Point(1) = {0, y0, 0};
Point(2) = {L, y0, 0};
Point(3) = {L, y1, 0};
Point(4) = {0, y1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Transfinite Curve {1, 3} = Round(L / h) + 1;
Transfinite Curve {2, 4} = Round((y1 - y0) / h) + 1;
Transfinite Surface {1};
Recombine Surface {1};

Physical Surface("pd", 11) = {1};
Physical Curve("left", 1)   = {4};
Physical Curve("right", 2)  = {2};
Physical Curve("bottom", 3) = {1};
Physical Curve("top", 4)    = {3};
