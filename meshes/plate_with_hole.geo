// plate_with_hole.geo -- long strip with a central circular hole.
//
// Strip x in [-2, 2], y in [-0.5, 0.5] (width W = 1), hole of radius 0.1 at
// the origin (d/W = 0.2). The strip is long (length/width = 4) so that the
// ends are far from the hole and the classical finite-width stress
// concentration factor for a hole in a strip under uniform tension applies.
// The peridynamic region is the band |x| <= 0.2 (full height) around the
// hole; the two ends are finite elements.
//
// Unstructured quadrilaterals. Cell size: h_hole at the hole, h_pd in the
// rest of the PD band, growing to h_far away from the band. The three
// surfaces share their interface edges, so the mesh is conforming. With the
// sizes below: 2819 quads (1626 PD, 1193 FE), 2934 nodes. The left end is
// split at (-2, 0) so that a node sits exactly there (the scene pins it in
// y to remove the rigid translation).
//
// Regions (material id = tag):    pd (11) band, fe (12) the two ends.
// Boundaries (boundary id = tag): left (1) x = -2, right (2) x = 2,
//                                 bottom (3) y = -0.5, top (4) y = 0.5,
//                                 hole (7) r = 0.1.

h_hole = 0.01;   // cell size on the hole edge
h_pd   = 0.02;   // cell size in the PD band away from the hole
h_far  = 0.1;    // cell size far from the band

A = 2.0;    // half length
B = 0.5;    // half width
b = 0.2;    // half width of the PD band
r = 0.1;    // hole radius

Mesh.ElementOrder = 1;

Point(1)  = {-A, -B, 0};
Point(2)  = {-b, -B, 0};
Point(3)  = { b, -B, 0};
Point(4)  = { A, -B, 0};
Point(5)  = {-A,  B, 0};
Point(6)  = {-b,  B, 0};
Point(7)  = { b,  B, 0};
Point(8)  = { A,  B, 0};
Point(9)  = { 0,  0, 0};   // hole centre
Point(10) = { r,  0, 0};
Point(11) = { 0,  r, 0};
Point(12) = {-r,  0, 0};
Point(13) = { 0, -r, 0};
Point(14) = {-A,  0, 0};   // mid-point of the left end (pinned node)

Line(1)  = {1, 2};   // bottom, left end
Line(2)  = {2, 3};   // bottom, band
Line(3)  = {3, 4};   // bottom, right end
Line(4)  = {5, 6};   // top, left end
Line(5)  = {6, 7};   // top, band
Line(6)  = {7, 8};   // top, right end
Line(7)  = {1, 14};  // x = -A, lower half
Line(15) = {14, 5};  // x = -A, upper half
Line(8)  = {2, 6};   // interface x = -b
Line(9)  = {3, 7};   // interface x = b
Line(10) = {4, 8};   // x = A
Circle(11) = {10, 9, 11};
Circle(12) = {11, 9, 12};
Circle(13) = {12, 9, 13};
Circle(14) = {13, 9, 10};

Curve Loop(1) = {1, 8, -4, -15, -7};
Curve Loop(2) = {2, 9, -5, -8};
Curve Loop(3) = {11, 12, 13, 14};
Curve Loop(4) = {3, 10, -6, -9};
Plane Surface(1) = {1};      // left FE end
Plane Surface(2) = {2, 3};   // PD band with the hole
Plane Surface(3) = {4};      // right FE end

// Cell size = min(field 2, field 3): field 2 grows from h_hole on the hole
// edge to h_pd at 2 r from it; field 3 is h_pd in the band and grows to
// h_far over a transition 0.6 wide outside it.
Field[1] = Distance;
Field[1].CurvesList = {11, 12, 13, 14};
Field[1].NumPointsPerCurve = 200;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_hole;
Field[2].SizeMax = h_pd;
Field[2].DistMin = 0;
Field[2].DistMax = 2 * r;
Field[2].StopAtDistMax = 1;
Field[3] = Box;
Field[3].VIn = h_pd;
Field[3].VOut = h_far;
Field[3].XMin = -b;
Field[3].XMax = b;
Field[3].YMin = -2 * B;
Field[3].YMax = 2 * B;
Field[3].Thickness = 0.6;
Field[4] = Min;
Field[4].FieldsList = {2, 3};
Background Field = 4;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;

// Frontal-Delaunay triangles recombined into quads by the Blossom
// algorithm. For the sizes above (and for them halved or doubled) this
// leaves no triangle; deal.II cannot mix quads and triangles, so if a
// refinement ever leaves one, use RecombinationAlgorithm = 3 (Blossom
// full-quad: all quads, by subdividing a mesh twice as coarse).
// Mesh.Algorithm = 8 (Frontal-Delaunay for quads) is avoided: it crashes in
// the gmsh 4.8.4 of Debian 12.
Mesh.Algorithm = 6;
Mesh.RecombinationAlgorithm = 1;
Mesh.RecombineAll = 1;

Physical Surface("pd", 11) = {2};
Physical Surface("fe", 12) = {1, 3};

Physical Curve("left", 1)   = {7, 15};
Physical Curve("right", 2)  = {10};
Physical Curve("bottom", 3) = {1, 2, 3};
Physical Curve("top", 4)    = {4, 5, 6};
Physical Curve("hole", 7)   = {11, 12, 13, 14};
