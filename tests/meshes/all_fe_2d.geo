// all_fe_2d.geo -- tiny all-finite-element mesh for the tests.
//
// Square [-0.5, 0.5]^2, 4 x 4 structured quadrilaterals, ONE region named
// "fe": there is no physical group "pd". Used by bad_empty_pd_region.prm to
// check that asking for "PD regions = pd" on it is reported as an input
// error. (It would also serve a pure-FE run with "PD regions = none".)
//
// Regions (material id = tag):    fe (12) everything.
// Boundaries (boundary id = tag): left (1) x = -0.5, right (2) x = 0.5,
//                                 bottom (3) y = -0.5, top (4) y = 0.5.

h = 0.25;   // target cell size

L = 0.5;    // half width and half height of the square
n = Round(2 * L / h);

Mesh.ElementOrder = 1;

Point(1) = {-L, -L, 0};
Point(2) = { L, -L, 0};
Point(3) = { L,  L, 0};
Point(4) = {-L,  L, 0};
Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // right
Line(3) = {3, 4};   // top
Line(4) = {4, 1};   // left
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Transfinite Curve {1, 2, 3, 4} = n + 1;
Transfinite Surface {1};
Recombine Surface {1};

Physical Surface("fe", 12) = {1};

Physical Curve("left", 1)   = {4};
Physical Curve("right", 2)  = {2};
Physical Curve("bottom", 3) = {1};
Physical Curve("top", 4)    = {3};
