// plate_with_hole.geo -- the mesh of tutorial step-1: a strip with a small
// central hole, for the stress concentration factor of a hole in tension.
//
// Strip x in [-1, 1], y in [-0.5, 0.5] (width W = 1, length 2W), hole of
// radius r = 0.05 at the origin (d/W = 0.1: a "small" hole, whose factor is
// within 1 % of Kirsch's 3 for the infinite plate). One region; the program
// decides which cells are peridynamic (those near the hole).
//
// Unstructured quadrilaterals (Frontal-Delaunay triangles recombined by
// Blossom): cell size h_hole on the hole edge (63 edges around it), growing
// to h_far over 0.3 from it. The left end is split at (-1, 0) so that a node
// sits exactly there (the program pins it in y).
//
// Region (material id = tag):     plate (1).
// Boundaries (boundary id = tag): left (1) x = -1, right (2) x = 1,
//                                 bottom (3), top (4), hole (5).

h_hole = 0.005; // cell size on the hole edge
h_far  = 0.06;  // cell size far from the hole

A = 1.0;  // half length
B = 0.5;  // half width
r = 0.05; // hole radius

Mesh.ElementOrder = 1;

Point(1) = {-A, -B, 0};
Point(2) = { A, -B, 0};
Point(3) = { A,  B, 0};
Point(4) = {-A,  B, 0};
Point(5) = {-A,  0, 0}; // mid-point of the left end (pinned node)
Point(6) = { 0,  0, 0}; // hole centre
Point(7) = { r,  0, 0};
Point(8) = { 0,  r, 0};
Point(9) = {-r,  0, 0};
Point(10) = {0, -r, 0};

Line(1) = {1, 2};  // bottom
Line(2) = {2, 3};  // right
Line(3) = {3, 4};  // top
Line(4) = {4, 5};  // left, upper half
Line(5) = {5, 1};  // left, lower half
Circle(6) = {7, 6, 8};
Circle(7) = {8, 6, 9};
Circle(8) = {9, 6, 10};
Circle(9) = {10, 6, 7};

Curve Loop(1) = {1, 2, 3, 4, 5};
Curve Loop(2) = {6, 7, 8, 9};
Plane Surface(1) = {1, 2};

// Cell size: h_hole on the hole edge, growing linearly to h_far at 0.3 from
// it (Threshold of the distance to the hole).
Field[1] = Distance;
Field[1].CurvesList = {6, 7, 8, 9};
Field[1].NumPointsPerCurve = 200;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_hole;
Field[2].SizeMax = h_far;
Field[2].DistMin = 0;
Field[2].DistMax = 0.3;
Background Field = 2;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;

// deal.II reads quadrilaterals or triangles, not both: recombine all.
// (Mesh.Algorithm = 8 crashes in the gmsh 4.8.4 of Debian 12.)
Mesh.Algorithm = 6;
Mesh.RecombinationAlgorithm = 1;
Mesh.RecombineAll = 1;

Physical Surface("plate", 1) = {1};
Physical Curve("left", 1)   = {4, 5};
Physical Curve("right", 2)  = {2};
Physical Curve("bottom", 3) = {1};
Physical Curve("top", 4)    = {3};
Physical Curve("hole", 5)   = {6, 7, 8, 9};
