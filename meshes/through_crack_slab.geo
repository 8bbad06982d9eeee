// through_crack_slab.geo -- a plate [-L, L] x [-H, H] with a structured PD box, extruded to a slab
// 0 <= z <= t of nz layers of hexahedra, for the K_I distribution along a through-thickness crack
// front with free faces (applications/examples/through_crack_3d). The in-plane mesh is that of
// tests/meshes/through_crack_plate.geo (PD box 30 x 15 cells of h = 0.01, ny odd so that y = 0 is a
// row of cell centres); here t = nz h.
//
// Regions (material id = tag):    pd (11) the box, fe (12) the rest.
// Boundaries (boundary id = tag): left (1), right (2), bottom (3), top (4),
//                                 back (5) z = 0, front (6) z = t.

h  = 0.01;     // PD cell size
nx = 30;       // PD cells in x
ny = 15;       // PD cells in y (odd)
L  = 0.5;      // half width of the plate (x)
H  = 1.5;      // half height (y): three widths long, a strip
hf = 0.06;     // cell size at the outer edges
bx = nx * h / 2;
by = ny * h / 2;

Mesh.ElementOrder = 1;
Mesh.RecombinationAlgorithm = 1;

Point(1) = {-L, -H, 0, hf};
Point(2) = { L, -H, 0, hf};
Point(3) = { L,  H, 0, hf};
Point(4) = {-L,  H, 0, hf};
Point(5) = {-bx, -by, 0, h};
Point(6) = { bx, -by, 0, h};
Point(7) = { bx,  by, 0, h};
Point(8) = {-bx,  by, 0, h};

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

Transfinite Curve {5, 7} = nx + 1;
Transfinite Curve {6, 8} = ny + 1;
Transfinite Surface {2};
Recombine Surface {1, 2};

nz = 8;        // layers through the thickness
t  = nz * h;   // thickness

frame[] = Extrude {0, 0, t} { Surface{1}; Layers{nz}; Recombine; };
box[]   = Extrude {0, 0, t} { Surface{2}; Layers{nz}; Recombine; };

Physical Volume("pd", 11) = {box[1]};
Physical Volume("fe", 12) = {frame[1]};

e = 1e-6;
Physical Surface("left", 1)   = Surface In BoundingBox {-L-e, -H-e, -e, -L+e,  H+e, t+e};
Physical Surface("right", 2)  = Surface In BoundingBox { L-e, -H-e, -e,  L+e,  H+e, t+e};
Physical Surface("bottom", 3) = Surface In BoundingBox {-L-e, -H-e, -e,  L+e, -H+e, t+e};
Physical Surface("top", 4)    = Surface In BoundingBox {-L-e,  H-e, -e,  L+e,  H+e, t+e};
Physical Surface("back", 5)   = Surface In BoundingBox {-L-e, -H-e, -e,  L+e,  H+e, e};
Physical Surface("front", 6)  = Surface In BoundingBox {-L-e, -H-e, t-e,  L+e,  H+e, t+e};
