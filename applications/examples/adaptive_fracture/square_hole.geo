// square_hole.geo -- case 2 of Hu et al. (specs/003 §5.1): the square
// [0, 0.05]^2 with a central hole of radius 5 mm on a lattice of spacing dx,
// with a 3 dx thick layer below and above it that the grips move. The cells
// whose centre lies in the hole are left out (lattice.geo).
//
// Boundaries (boundary id = tag): bottom (1) y = -3 dx, top (2)
// y = 0.05 + 3 dx. A file that sets dx and then includes this one gets
// another lattice (tests/meshes/square_hole_coarse.geo).

If (!Exists(dx))
  dx = 0.001;
EndIf
L  = 0.05;
R  = 0.005;
nx = Round(L / dx);
ny = nx + 6;
x0 = 0;
y0 = -3 * dx;

keep[] = {};
For j In {0 : ny - 1}
  For i In {0 : nx - 1}
    xc                = x0 + (i + 0.5) * dx - L / 2;
    yc                = y0 + (j + 0.5) * dx - L / 2;
    keep[j * nx + i] = xc * xc + yc * yc > R * R;
  EndFor
EndFor

Include "lattice.geo";

Physical Surface("plate", 11) = body[];
Physical Curve("bottom", 1)   = {1 : nx};
Physical Curve("top", 2)      = {1 + ny * nx : nx + ny * nx};
