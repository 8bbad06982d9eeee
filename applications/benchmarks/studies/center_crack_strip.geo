// center_crack_strip.geo -- the strip of tests/scenes/sif_center_crack_strip.prm (meshes/cracked_strip.geo)
// with cell counts that follow pdfem's `Mesh/Mesh size factor` (gmsh -clscale), so that a study can
// refine it: h = 0.02 x the factor in the PD band, 2 h in the FE blocks.
//
// Strip [-0.5, 0.5] x [-1.5, 1.5]; PD band |y| <= 0.15 (region pd, 11) between two FE blocks (fe, 12);
// boundaries left (1), right (2), bottom (3), top (4). Structured quadrilaterals, conforming at the
// interfaces. The band gets an odd number of cells across its height, so that the crack line y = 0
// is a row of cell centres: no node lies on it. The cells across the width are an even number, so
// that the tips x = +-0.2107 of the scene's crack fall between node columns for the factors used in
// applications/benchmarks/studies/run.sh (1, 0.7, 0.5, 0.4: 50, 72, 100, 126 cells).

h  = 0.02 * Mesh.MeshSizeFactor;   // cell size in the band
W  = 0.5;                          // half width
H  = 1.5;                          // half height
B  = 0.15;                         // half height of the PD band
nx = 2 * Round(W / h);             // cells across
ny = 2 * Floor(B / h) + 1;         // cells across the band (odd)
nb = Round((H - B) / (2 * h));     // cells over the height of each FE block

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

Transfinite Curve {1, 3, 6, 9}  = nx + 1;
Transfinite Curve {5, 7}        = ny + 1;
Transfinite Curve {2, 4, 8, 10} = nb + 1;
Transfinite Surface {1, 2, 3};
Recombine Surface {1, 2, 3};

Physical Surface("pd", 11) = {2};
Physical Surface("fe", 12) = {1, 3};
Physical Curve("left", 1)   = {4, 7, 10};
Physical Curve("right", 2)  = {2, 5, 8};
Physical Curve("bottom", 3) = {1};
Physical Curve("top", 4)    = {9};
