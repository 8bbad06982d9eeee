// rnp_cracked_plate.geo -- the pre-cracked square plate of specs/000 §4.5-4.6
// (15 x 15, pre-crack (0, 7.5) -- (7.5, 7.5) given in the scene), coarser
// than the paper: 45 x 45 quadrilaterals, h = 1/3 (2116 nodes; node rows at
// y = 7.33 and 7.67, none on the crack line). All PD.
//
// Regions (material id = tag):    pd (11) everything.
// Boundaries (boundary id = tag): left (1) x = 0, right (2) x = 15,
//                                 bottom (3) y = 0, top (4) y = 15.

L = 15;
n = 45;

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
