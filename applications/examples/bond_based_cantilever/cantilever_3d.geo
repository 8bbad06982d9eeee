// cantilever_3d.geo -- the 3D cantilever of Hu et al. (specs/003 §5.1, case 1; the book benchmark of
// Madenci & Oterkus): the beam [0, 1] x [0, 0.1] x [0, 0.1] on a lattice of spacing dx and, left of it,
// the 3 dx thick layer [-3 dx, 0] the supports hold. Structured hexahedra, every cell PD.
//
// Boundaries (boundary id = tag): left (1) x = -3 dx, right (2) x = 1.

// dx = 2 cm times Mesh/Mesh size factor (gmsh -clscale sets Mesh.MeshSizeFactor before it reads this
// file): the paper's 1 cm (8 times the nodes) is `--set "Mesh/Mesh size factor=0.5"`.
dx = 0.02 * Mesh.MeshSizeFactor;
L  = 1.0;
W  = 0.1;

Mesh.ElementOrder = 1;

Point(1) = {-3 * dx, 0, 0};
Point(2) = {L, 0, 0};
Point(3) = {L, W, 0};
Point(4) = {-3 * dx, W, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve {1, 3} = Round((L + 3 * dx) / dx) + 1;
Transfinite Curve {2, 4} = Round(W / dx) + 1;
Transfinite Surface {1};
Recombine Surface {1};
out[] = Extrude {0, 0, W} { Surface{1}; Layers{Round(W / dx)}; Recombine; };
// out[0] top, out[1] volume, out[2..5] the sides of lines 1..4

Physical Volume("beam", 11) = {out[1]};
Physical Surface("left", 1)  = {out[5]};
Physical Surface("right", 2) = {out[3]};
