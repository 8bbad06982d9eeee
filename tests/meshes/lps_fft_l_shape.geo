// lps_fft_l_shape.geo -- an L-shaped plate of equal square cells (the uniform grid of
// Peridynamics/Model = lps fft, a body that does not fill its bounding box).
//
// [0, 1] x [0, 0.5] and [0, 0.5] x [0.5, 1]: three transfinite squares of 0.5 x 0.5 with
// n = 10 cells per side (h = 0.05), conforming where they meet: 300 cells, 341 nodes.
//
// Regions (material id = tag):    plate (11).
// Boundaries (boundary id = tag): left (1) x = 0, bottom (2) y = 0, right (3) x = 1,
//                                 top (4) the edges y = 0.5 (x > 0.5) and y = 1.

n = 10;    // cells per side of each square

Mesh.ElementOrder = 1;

Point(1) = {0,   0,   0};
Point(2) = {0.5, 0,   0};
Point(3) = {1,   0,   0};
Point(4) = {0,   0.5, 0};
Point(5) = {0.5, 0.5, 0};
Point(6) = {1,   0.5, 0};
Point(7) = {0,   1,   0};
Point(8) = {0.5, 1,   0};

Line(1)  = {1, 2};   // bottom, left square
Line(2)  = {2, 3};   // bottom, right square
Line(3)  = {4, 5};   // y = 0.5, left
Line(4)  = {5, 6};   // y = 0.5, right (top edge)
Line(5)  = {7, 8};   // y = 1
Line(6)  = {1, 4};   // x = 0, lower
Line(7)  = {4, 7};   // x = 0, upper
Line(8)  = {2, 5};   // x = 0.5, lower
Line(9)  = {5, 8};   // x = 0.5, upper (right edge of the upper square)
Line(10) = {3, 6};   // x = 1

// counter-clockwise loops: every cell is positively oriented
Curve Loop(1) = {1, 8, -3, -6};
Curve Loop(2) = {2, 10, -4, -8};
Curve Loop(3) = {3, 9, -5, -7};
Plane Surface(1) = {1};
Plane Surface(2) = {2};
Plane Surface(3) = {3};

Transfinite Curve {1:10} = n + 1;
Transfinite Surface {1, 2, 3};
Recombine Surface {1, 2, 3};

Physical Surface("plate", 11) = {1, 2, 3};

Physical Curve("left", 1)   = {6, 7};
Physical Curve("bottom", 2) = {1, 2};
Physical Curve("right", 3)  = {10};
Physical Curve("top", 4)    = {4, 5};
Physical Curve("inner", 5)  = {9};
