// patch_3d_tet.geo -- small 3D patch-test mesh of tetrahedra for the tests.
//
// Box [-0.5, 0.5] x [-0.5, 0.5] x [-0.25, 0.25] with a peridynamic slab
// |x| <= 0.2 (full height and depth) between two finite-element blocks, as
// patch_3d_hex.geo, but meshed with unstructured tetrahedra. The three boxes
// are fragmented against each other, so they share their interface faces
// and the mesh is conforming.
//
// Regions (material id = tag):    pd (11) slab, fe (12) the two outer blocks.
// Boundaries (boundary id = tag): left (1) x = -0.5, right (2) x = 0.5,
//                                 bottom (3) y = -0.5, top (4) y = 0.5,
//                                 back (5) z = -0.25, front (6) z = 0.25.

h = 0.2;    // target cell size

L = 0.5;    // half size in x and y
T = 0.25;   // half size in z
b = 0.2;    // half width of the PD slab

SetFactory("OpenCASCADE");
Mesh.ElementOrder = 1;
Mesh.MeshSizeMin = h;
Mesh.MeshSizeMax = h;

Box(1) = {-L, -L, -T, L - b, 2 * L, 2 * T};   // left FE block
Box(2) = {-b, -L, -T, 2 * b, 2 * L, 2 * T};   // PD slab
Box(3) = { b, -L, -T, L - b, 2 * L, 2 * T};   // right FE block
BooleanFragments{ Volume{1, 2, 3}; Delete; }{}

e = 1e-6;   // tolerance of the bounding boxes below
Physical Volume("pd", 11) = Volume In BoundingBox {-b-e, -L-e, -T-e, b+e, L+e, T+e};
Physical Volume("fe", 12) = Volume In BoundingBox {-L-e, -L-e, -T-e, -b+e, L+e, T+e};
Physical Volume("fe", 12) += Volume In BoundingBox {b-e, -L-e, -T-e, L+e, L+e, T+e};

Physical Surface("left", 1)   = Surface In BoundingBox {-L-e, -L-e, -T-e, -L+e,  L+e,  T+e};
Physical Surface("right", 2)  = Surface In BoundingBox { L-e, -L-e, -T-e,  L+e,  L+e,  T+e};
Physical Surface("bottom", 3) = Surface In BoundingBox {-L-e, -L-e, -T-e,  L+e, -L+e,  T+e};
Physical Surface("top", 4)    = Surface In BoundingBox {-L-e,  L-e, -T-e,  L+e,  L+e,  T+e};
Physical Surface("back", 5)   = Surface In BoundingBox {-L-e, -L-e, -T-e,  L+e,  L+e, -T+e};
Physical Surface("front", 6)  = Surface In BoundingBox {-L-e, -L-e,  T-e,  L+e,  L+e,  T+e};
