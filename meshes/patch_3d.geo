// patch_3d.geo -- 3D uniform-tension patch test.
//
// Box [-0.5, 0.5] x [-0.5, 0.5] x [-0.25, 0.25] with a peridynamic slab
// |x| <= 0.2 (full height and depth) between two finite-element blocks.
// Structured hexahedra: a structured quad mesh of the bottom face z = -0.25
// is extruded in z. Conforming across the PD/FE interfaces.
// With h = 1/16: 5 + 6 + 5 = 16 cells in x (FE 0.06, PD 0.0667 wide),
// 16 in y, 8 in z: 2048 cells, 2601 nodes.
//
// Regions (material id = tag):    pd (11) slab, fe (12) the two outer blocks.
// Boundaries (boundary id = tag): left (1) x = -0.5, right (2) x = 0.5,
//                                 bottom (3) y = -0.5, top (4) y = 0.5,
//                                 back (5) z = -0.25, front (6) z = 0.25.

h = 1 / 16;   // target cell size: change this one number to refine

L = 0.5;      // half size in x and y
T = 0.25;     // half size in z
b = 0.2;      // half width of the PD slab

nfe = Round((L - b) / h);   // cells across each FE block
npd = Round(2 * b / h);     // cells across the PD slab
ny  = Round(2 * L / h);     // cells in y
nz  = Round(2 * T / h);     // cells in z

Mesh.ElementOrder = 1;

// bottom face z = -T, as in patch_2d.geo
Point(1) = {-L, -L, -T};
Point(2) = {-b, -L, -T};
Point(3) = { b, -L, -T};
Point(4) = { L, -L, -T};
Point(5) = {-L,  L, -T};
Point(6) = {-b,  L, -T};
Point(7) = { b,  L, -T};
Point(8) = { L,  L, -T};

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
Plane Surface(1) = {1};   // left FE block
Plane Surface(2) = {2};   // PD slab
Plane Surface(3) = {3};   // right FE block

Transfinite Curve {1, 3, 4, 6}  = nfe + 1;
Transfinite Curve {2, 5}        = npd + 1;
Transfinite Curve {7, 8, 9, 10} = ny + 1;
Transfinite Surface {1, 2, 3};
Recombine Surface {1, 2, 3};

// extrude the three blocks together, so that they share the interface faces
left_block[]  = Extrude {0, 0, 2 * T} { Surface{1}; Layers{nz}; Recombine; };
slab[]        = Extrude {0, 0, 2 * T} { Surface{2}; Layers{nz}; Recombine; };
right_block[] = Extrude {0, 0, 2 * T} { Surface{3}; Layers{nz}; Recombine; };
// (Extrude returns the top surface, then the volume, then the side faces)

Physical Volume("pd", 11) = {slab[1]};
Physical Volume("fe", 12) = {left_block[1], right_block[1]};

e = 1e-6;   // tolerance of the bounding boxes below
Physical Surface("left", 1)   = Surface In BoundingBox {-L-e, -L-e, -T-e, -L+e,  L+e,  T+e};
Physical Surface("right", 2)  = Surface In BoundingBox { L-e, -L-e, -T-e,  L+e,  L+e,  T+e};
Physical Surface("bottom", 3) = Surface In BoundingBox {-L-e, -L-e, -T-e,  L+e, -L+e,  T+e};
Physical Surface("top", 4)    = Surface In BoundingBox {-L-e,  L-e, -T-e,  L+e,  L+e,  T+e};
Physical Surface("back", 5)   = Surface In BoundingBox {-L-e, -L-e, -T-e,  L+e,  L+e, -T+e};
Physical Surface("front", 6)  = Surface In BoundingBox {-L-e, -L-e,  T-e,  L+e,  L+e,  T+e};
