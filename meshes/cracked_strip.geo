// cracked_strip.geo -- a long strip for handbook cracks and crack growth.
//
// [-0.5, 0.5] x [-1.5, 1.5] (W = 1, H = 3: H / W = 3, long enough that the
// handbook formulas for an infinitely long strip hold). A peridynamic band
// |y| <= 0.15 through the full width, between two finite-element blocks;
// structured quadrilaterals everywhere, conforming across the interfaces.
// The band has an odd number of cells in y (15, h = 0.02), so that y = 0 is
// a row of cell centres: a crack on y = 0 passes no node.
//
// Cracks are not in the mesh (scene parameters): an edge crack from
// (-0.5, 0), or a centre crack about (0, 0).
//
// Regions (material id = tag):    pd (11) the band, fe (12) the blocks.
// Boundaries (boundary id = tag): left (1), right (2), bottom (3), top (4).

nx = 50;    // cells across (h = 0.02)
ny = 15;    // cells across the band (odd)
nb = 34;    // cells over the height of each FE block (h about 0.04)
W  = 0.5;
H  = 1.5;
B  = 0.15;

// A file that sets fe_triangles = 1 and then includes this one gets the FE
// blocks in triangles: a mesh of two kinds of cell.
If (!Exists(fe_triangles))
  fe_triangles = 0;
EndIf

Mesh.ElementOrder = 1;

Point(1) = {-W, -H, 0};
Point(2) = { W, -H, 0};
Point(3) = { W, -B, 0};
Point(4) = {-W, -B, 0};
Point(5) = { W,  B, 0};
Point(6) = {-W,  B, 0};
Point(7) = { W,  H, 0};
Point(8) = {-W,  H, 0};

Line(1)  = {1, 2};   // bottom
Line(2)  = {2, 3};   // right, lower block
Line(3)  = {3, 4};   // lower interface
Line(4)  = {4, 1};   // left, lower block
Line(5)  = {3, 5};   // right, band
Line(6)  = {5, 6};   // upper interface
Line(7)  = {6, 4};   // left, band
Line(8)  = {5, 7};   // right, upper block
Line(9)  = {7, 8};   // top
Line(10) = {8, 6};   // left, upper block

Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {-3, 5, 6, 7};
Curve Loop(3) = {-6, 8, 9, 10};
Plane Surface(1) = {1};
Plane Surface(2) = {2};
Plane Surface(3) = {3};

Transfinite Curve {1, 3, 6, 9} = nx + 1;
Transfinite Curve {5, 7}       = ny + 1;
Transfinite Curve {2, 4, 8, 10} = nb + 1;
Transfinite Surface {1, 2, 3};
Recombine Surface {2};
If (!fe_triangles)
  Recombine Surface {1, 3};
EndIf

Physical Surface("pd", 11) = {2};
Physical Surface("fe", 12) = {1, 3};
Physical Curve("left", 1)   = {4, 7, 10};
Physical Curve("right", 2)  = {2, 5, 8};
Physical Curve("bottom", 3) = {1};
Physical Curve("top", 4)    = {9};
