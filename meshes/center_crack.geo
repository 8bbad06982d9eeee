// center_crack.geo -- square plate for the centre-crack example.
//
// Square [-0.5, 0.5]^2 with a peridynamic strip |x| <= 0.2 (full height)
// between two finite-element blocks. Structured quadrilaterals, conforming
// across the PD/FE interfaces. The crack itself is NOT in the mesh: it is a
// pre-existing crack of the parameter file (bonds crossing it are cut), on
// the line x = 0 from y = -0.098 to y = 0.098.
//
// The strip gets an ODD number of cells across, so that x = 0 is a row of
// cell centres, not a row of nodes: no PD node lies on the crack line and
// every bond crossing it is cut unambiguously. With h = 0.0125:
// 24 + 33 + 24 = 81 cells across (strip spacing 0.4/33 = 0.0121),
// 80 cells high, 6480 cells, 6642 nodes.
//
// The left edge is split at (-0.5, 0) so that a node sits exactly there
// (the scene pins it in y to remove the rigid translation).
//
// Regions (material id = tag):    pd (11) strip, fe (12) the two outer blocks.
// Boundaries (boundary id = tag): left (1) x = -0.5, right (2) x = 0.5,
//                                 bottom (3) y = -0.5, top (4) y = 0.5.

h = 0.0125;   // target cell size: change this one number to refine

L = 0.5;      // half width and half height of the plate
b = 0.2;      // half width of the PD strip

nfe = Round((L - b) / h);        // cells across each FE block
npd = 2 * Round(b / h) + 1;      // cells across the PD strip (odd)
nh  = Round(L / h);              // cells over half the height

Mesh.ElementOrder = 1;

Point(1) = {-L, -L, 0};
Point(2) = {-b, -L, 0};
Point(3) = { b, -L, 0};
Point(4) = { L, -L, 0};
Point(5) = {-L,  L, 0};
Point(6) = {-b,  L, 0};
Point(7) = { b,  L, 0};
Point(8) = { L,  L, 0};
Point(9) = {-L,  0, 0};   // mid-point of the left edge (pinned node)

Line(1)  = {1, 2};   // bottom, left block
Line(2)  = {2, 3};   // bottom, strip
Line(3)  = {3, 4};   // bottom, right block
Line(4)  = {5, 6};   // top, left block
Line(5)  = {6, 7};   // top, strip
Line(6)  = {7, 8};   // top, right block
Line(7)  = {1, 9};   // x = -L, lower half
Line(11) = {9, 5};   // x = -L, upper half
Line(8)  = {2, 6};   // interface x = -b
Line(9)  = {3, 7};   // interface x = b
Line(10) = {4, 8};   // x = L

Curve Loop(1) = {1, 8, -4, -11, -7};
Curve Loop(2) = {2, 9, -5, -8};
Curve Loop(3) = {3, 10, -6, -9};
Plane Surface(1) = {1};   // left FE block
Plane Surface(2) = {2};   // PD strip
Plane Surface(3) = {3};   // right FE block

Transfinite Curve {1, 3, 4, 6} = nfe + 1;
Transfinite Curve {2, 5}       = npd + 1;
Transfinite Curve {8, 9, 10}   = 2 * nh + 1;
Transfinite Curve {7, 11}      = nh + 1;
Transfinite Surface {1} = {1, 2, 6, 5};   // corners (point 9 is on a side)
Transfinite Surface {2, 3};
Recombine Surface {1, 2, 3};

Physical Surface("pd", 11) = {2};
Physical Surface("fe", 12) = {1, 3};

Physical Curve("left", 1)   = {7, 11};
Physical Curve("right", 2)  = {10};
Physical Curve("bottom", 3) = {1, 2, 3};
Physical Curve("top", 4)    = {4, 5, 6};
