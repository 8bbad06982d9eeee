// inclined_crack.geo -- large square plate with a fine peridynamic box in
// the middle, for the inclined central crack of Liu & Xin (EFM 2021, §5.1;
// specs/004 §6.1).
//
// Square [-0.5, 0.5]^2 (W = 1 m). The box [-b, b]^2, b = 0.05, is a
// structured n x n grid of quadrilaterals (n = 39: 1521 cells, h = 2.56 mm,
// the paper's Q4 mesh); n is odd, so the centre lines x = 0 and y = 0 are
// rows of cell centres, not of nodes. Outside the box, unstructured
// quadrilaterals grow from h at the box to hf at the outer edges.
// The crack (2a = 40 mm, any angle) is NOT in the mesh: it is a
// pre-existing crack of the scene, whose bonds are cut.
//
// Regions (material id = tag):    pd (11) the box, fe (12) the rest.
// Boundaries (boundary id = tag): bottom (3) y = -0.5, top (4) y = 0.5,
//                                 left (1), right (2).

n  = 39;     // cells across the PD box (odd)
hf = 0.05;   // cell size at the outer edges
L  = 0.5;
b  = 0.05;
h  = 2 * b / n;

Mesh.ElementOrder = 1;
Mesh.RecombinationAlgorithm = 1;

Point(1) = {-L, -L, 0, hf};
Point(2) = { L, -L, 0, hf};
Point(3) = { L,  L, 0, hf};
Point(4) = {-L,  L, 0, hf};
Point(5) = {-b, -b, 0, h};
Point(6) = { b, -b, 0, h};
Point(7) = { b,  b, 0, h};
Point(8) = {-b,  b, 0, h};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};

Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};   // FE frame
Plane Surface(2) = {2};      // PD box

Transfinite Curve {5, 6, 7, 8} = n + 1;
Transfinite Surface {2};
Recombine Surface {1, 2};

Physical Surface("pd", 11) = {2};
Physical Surface("fe", 12) = {1};
Physical Curve("left", 1)   = {4};
Physical Curve("right", 2)  = {2};
Physical Curve("bottom", 3) = {1};
Physical Curve("top", 4)    = {3};
