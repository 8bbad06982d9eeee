// through_crack_plate.geo -- the in-plane geometry shared by through_crack_2d.geo
// and through_crack_3d.geo (the 3D one extrudes it), for the 2D/3D comparison of
// the interaction integral (tests/scenes/sif_through_crack_*.prm).
//
// Plate [-L, L] x [-H, H] in the plane z = 0 with a structured PD box [-bx, bx] x
// [-by, by] of nx x ny square cells of size h (ny odd: y = 0 is a row of cell
// centres, so that a crack on y = 0 passes between node rows), and unstructured
// quadrilaterals outside growing from h to hf at the edges. Defines the surfaces
// 1 (FE frame) and 2 (PD box) and the curves 1-4 of the outer edges (bottom,
// right, top, left); the including file adds the physical groups.

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
