// patch_2d_tri.geo -- small 2D patch-test mesh of triangles for the tests.
//
// Square [-0.5, 0.5]^2 with a peridynamic slab |x| <= 0.2 (full height)
// between two finite-element blocks, as patch_2d_quad.geo, but meshed with
// unstructured triangles (Frontal-Delaunay), so that the PD nodes are
// irregularly spaced. The blocks share their interface edges: conforming.
//
// Regions (material id = tag):    pd (11) slab, fe (12) the two outer blocks.
// Boundaries (boundary id = tag): left (1) x = -0.5, right (2) x = 0.5,
//                                 bottom (3) y = -0.5, top (4) y = 0.5.

h = 0.1;    // target cell size

L = 0.5;    // half width and half height of the square
b = 0.2;    // half width of the PD slab

Mesh.ElementOrder = 1;
Mesh.Algorithm = 6;   // Frontal-Delaunay
Mesh.MeshSizeMin = h;
Mesh.MeshSizeMax = h;

Point(1) = {-L, -L, 0, h};
Point(2) = {-b, -L, 0, h};
Point(3) = { b, -L, 0, h};
Point(4) = { L, -L, 0, h};
Point(5) = {-L,  L, 0, h};
Point(6) = {-b,  L, 0, h};
Point(7) = { b,  L, 0, h};
Point(8) = { L,  L, 0, h};

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

Curve Loop(1) = {1, 8, -4, -7};
Curve Loop(2) = {2, 9, -5, -8};
Curve Loop(3) = {3, 10, -6, -9};
Plane Surface(1) = {1};   // left FE block
Plane Surface(2) = {2};   // PD slab
Plane Surface(3) = {3};   // right FE block

Physical Surface("pd", 11) = {2};
Physical Surface("fe", 12) = {1, 3};

Physical Curve("left", 1)   = {7};
Physical Curve("right", 2)  = {10};
Physical Curve("bottom", 3) = {1, 2, 3};
Physical Curve("top", 4)    = {4, 5, 6};
