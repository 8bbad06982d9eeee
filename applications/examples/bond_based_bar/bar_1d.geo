// bar_1d.geo -- the 1D bar of Hu et al. (specs/003 §5.1, case A) as a strip one cell tall: the bar
// [0, 1] x [0, dx] on square cells of size dx and, left of it, the 3 dx layer [-3 dx, 0] the support
// holds. With Peridynamics/Bond based/Body = uniaxial bar the strip's two lines of nodes are two
// bars along x (bonds along x only).
//
// dx = 0.01 times Mesh/Mesh size factor (gmsh -clscale sets Mesh.MeshSizeFactor before it reads this
// file), so `--set "Mesh/Mesh size factor=0.1"` gives dx = 1 mm: the paper's resolutions 1/10 to
// 1/20000 m are factors 10 to 0.005.
//
// Boundaries (boundary id = tag): left (1) x = -3 dx, right (2) x = 1, bottom (3) y = 0, top (4)
// y = dx; every node lies on bottom or top.

dx = 0.01 * Mesh.MeshSizeFactor;
L  = 1.0;

Mesh.ElementOrder = 1;

Point(1) = {-3 * dx, 0, 0};
Point(2) = {L, 0, 0};
Point(3) = {L, dx, 0};
Point(4) = {-3 * dx, dx, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve {1, 3} = Round((L + 3 * dx) / dx) + 1;
Transfinite Curve {2, 4} = 2;
Transfinite Surface {1};
Recombine Surface {1};

Physical Surface("bar", 11) = {1};
Physical Curve("left", 1)   = {4};
Physical Curve("right", 2)  = {2};
Physical Curve("bottom", 3) = {1};
Physical Curve("top", 4)    = {3};
