// patch_2d.geo -- 2D uniform-tension patch test.
//
// Square [-0.5, 0.5]^2 with a peridynamic slab |x| <= 0.2 (full height)
// between two finite-element blocks. Structured quadrilaterals, conforming
// across the PD/FE interfaces (the blocks share their vertical edges).
// With h = 0.05: 6 + 8 + 6 = 20 cells across, 20 cells high (400 cells).
//
// Regions (material id = tag):    pd (11) slab, fe (12) the two outer blocks.
// Boundaries (boundary id = tag): left (1) x = -0.5, right (2) x = 0.5,
//                                 bottom (3) y = -0.5, top (4) y = 0.5.

h = 0.05;   // target cell size: change this one number to refine

L  = 0.5;   // half width and half height of the square
b  = 0.2;   // half width of the PD slab

nfe = Round((L - b) / h);   // cells across each FE block
npd = Round(2 * b / h);     // cells across the PD slab
ny  = Round(2 * L / h);     // cells over the height

Mesh.ElementOrder = 1;

// corner points, bottom row then top row (x = -L, -b, b, L)
Point(1) = {-L, -L, 0};
Point(2) = {-b, -L, 0};
Point(3) = { b, -L, 0};
Point(4) = { L, -L, 0};
Point(5) = {-L,  L, 0};
Point(6) = {-b,  L, 0};
Point(7) = { b,  L, 0};
Point(8) = { L,  L, 0};

Line(1)  = {1, 2};   // bottom, left block
Line(2)  = {2, 3};   // bottom, slab
Line(3)  = {3, 4};   // bottom, right block
Line(4)  = {5, 6};   // top, left block
Line(5)  = {6, 7};   // top, slab
Line(6)  = {7, 8};   // top, right block
Line(7)  = {1, 5};   // x = -L
Line(8)  = {2, 6};   // interface x = -b
Line(9)  = {3, 7};   // interface x = b
Line(10) = {4, 8};   // x = L

// counter-clockwise loops: every cell is positively oriented
Curve Loop(1) = {1, 8, -4, -7};
Curve Loop(2) = {2, 9, -5, -8};
Curve Loop(3) = {3, 10, -6, -9};
Plane Surface(1) = {1};   // left FE block
Plane Surface(2) = {2};   // PD slab
Plane Surface(3) = {3};   // right FE block

Transfinite Curve {1, 3, 4, 6} = nfe + 1;
Transfinite Curve {2, 5}       = npd + 1;
Transfinite Curve {7, 8, 9, 10} = ny + 1;
Transfinite Surface {1, 2, 3};
Recombine Surface {1, 2, 3};

Physical Surface("pd", 11) = {2};
Physical Surface("fe", 12) = {1, 3};

Physical Curve("left", 1)   = {7};
Physical Curve("right", 2)  = {10};
Physical Curve("bottom", 3) = {1, 2, 3};
Physical Curve("top", 4)    = {4, 5, 6};
