// bar_2d.geo -- a slender bar for the wave-propagation tests.
//
// [0, 1] x [0, 0.05], structured quadrilaterals of size h = 0.01
// (100 x 5 = 500 cells, 606 nodes), a PD slab 0.4 <= x <= 0.6 between two
// FE blocks (conforming at the interfaces). A scene makes it all FE with
// "PD regions = none".
//
// Regions (material id = tag):    pd (11) slab, fe (12) the two blocks.
// Boundaries (boundary id = tag): left (1) x = 0, right (2) x = 1,
//                                 bottom (3) y = 0, top (4) y = 0.05.

h  = 0.01;   // target cell size
L  = 1.0;    // length
H  = 0.05;   // height
a  = 0.4;    // slab start
b  = 0.6;    // slab end

Mesh.ElementOrder = 1;

Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0};
Point(3) = {b, 0, 0};
Point(4) = {L, 0, 0};
Point(5) = {0, H, 0};
Point(6) = {a, H, 0};
Point(7) = {b, H, 0};
Point(8) = {L, H, 0};

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
Plane Surface(1) = {1};
Plane Surface(2) = {2};
Plane Surface(3) = {3};

Transfinite Curve {1, 4} = Round(a / h) + 1;
Transfinite Curve {2, 5} = Round((b - a) / h) + 1;
Transfinite Curve {3, 6} = Round((L - b) / h) + 1;
Transfinite Curve {7, 8, 9, 10} = Round(H / h) + 1;
Transfinite Surface {1, 2, 3};
Recombine Surface {1, 2, 3};

Physical Surface("pd", 11) = {2};
Physical Surface("fe", 12) = {1, 3};

Physical Curve("left", 1)   = {7};
Physical Curve("right", 2)  = {10};
Physical Curve("bottom", 3) = {1, 2, 3};
Physical Curve("top", 4)    = {4, 5, 6};
