// cantilever_2d.geo -- the 2D cantilever of Hu et al. (specs/003 §5.1, case B)
// on a lattice of spacing dx: the beam [0, 0.5] x [0, 0.05] and, left of it,
// the 3 dx thick layer [-3 dx, 0] the supports hold (the fictitious layer).
// Structured quadrilaterals; every cell is PD (the scene says so).
//
// Boundaries (boundary id = tag): left (1) x = -3 dx, right (2) x = 0.5.

dx = 0.005;
L  = 0.5;
W  = 0.05;

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

Physical Surface("beam", 11) = {1};
Physical Curve("left", 1)  = {4};
Physical Curve("right", 2) = {2};
