// lps_fft_bar_3d.geo -- a 3D bar of equal cubes (the uniform grid of Peridynamics/Model = lps fft):
// [0, 0.3] x [0, 0.3] x [0, 0.7] with h = 0.05: 6 x 6 x 14 cells, 7 x 7 x 15 = 735 nodes. A square
// of structured quadrilaterals extruded in z.
//
// Regions (material id = tag):    bar (11).
// Boundaries (boundary id = tag): bottom (1) z = 0, top (2) z = 0.7, sides (3).

h = 0.05;
a = 0.3;
l = 0.7;

Mesh.ElementOrder = 1;

Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0};
Point(3) = {a, a, 0};
Point(4) = {0, a, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve {1, 2, 3, 4} = a / h + 1;
Transfinite Surface {1};
Recombine Surface {1};
bar[] = Extrude {0, 0, l} { Surface{1}; Layers{l / h}; Recombine; };

Physical Volume("bar", 11)    = {bar[1]};
Physical Surface("bottom", 1) = {1};
Physical Surface("top", 2)    = {bar[0]};
Physical Surface("sides", 3)  = {bar[2], bar[3], bar[4], bar[5]};
