// lps_fft_notched_plate.geo -- a plate with an edge notch, of equal square cells (the uniform grid
// of Peridynamics/Model = lps fft), for the energy criterion's crack (lps_fft_damage_*.prm).
//
// [0, 20] x [0, 8] mm, h = 0.25 mm (80 x 32 cells). The notch [0, 10] x [3.5, 4.5] mm holds no
// cell: the grid rows y = 3.75, 4, 4.25 mm have no node for x < 10 mm, so the nodes on either
// side are 1 mm > delta = 3.015 h = 0.754 mm apart and share no bond (a notch of dead nodes,
// specs/002 §4.2). Five transfinite blocks, conforming where they meet: 2400 cells, 2553 nodes.
//
// Regions (material id = tag):    plate (11).
// Boundaries (boundary id = tag): bottom (1) y = 0, top (2) y = 8 mm, notch (3) its faces.

h  = 0.25e-3;   // cell size
L  = 20e-3;     // width
H  = 8e-3;      // height
a  = 10e-3;     // notch length
y1 = 3.5e-3;    // notch faces
y2 = 4.5e-3;

Mesh.ElementOrder = 1;

Point(1)  = {0, 0, 0};
Point(2)  = {a, 0, 0};
Point(3)  = {L, 0, 0};
Point(4)  = {0, y1, 0};
Point(5)  = {a, y1, 0};
Point(6)  = {L, y1, 0};
Point(7)  = {0, y2, 0};
Point(8)  = {a, y2, 0};
Point(9)  = {L, y2, 0};
Point(10) = {0, H, 0};
Point(11) = {a, H, 0};
Point(12) = {L, H, 0};

Line(1)  = {1, 2};    // y = 0
Line(2)  = {2, 3};
Line(3)  = {4, 5};    // y = y1 (lower notch face)
Line(4)  = {5, 6};
Line(5)  = {7, 8};    // y = y2 (upper notch face)
Line(6)  = {8, 9};
Line(7)  = {10, 11};  // y = H
Line(8)  = {11, 12};
Line(9)  = {1, 4};    // x = 0
Line(10) = {2, 5};    // x = a
Line(11) = {3, 6};    // x = L
Line(12) = {5, 8};    // x = a, notch tip
Line(13) = {6, 9};
Line(14) = {7, 10};   // x = 0
Line(15) = {8, 11};
Line(16) = {9, 12};

Curve Loop(1) = {1, 10, -3, -9};
Curve Loop(2) = {2, 11, -4, -10};
Curve Loop(3) = {4, 13, -6, -12};
Curve Loop(4) = {5, 15, -7, -14};
Curve Loop(5) = {6, 16, -8, -15};
For s In {1:5}
  Plane Surface(s) = {s};
EndFor

Transfinite Curve {1, 3, 5, 7} = Round(a / h) + 1;
Transfinite Curve {2, 4, 6, 8} = Round((L - a) / h) + 1;
Transfinite Curve {9, 10, 11} = Round(y1 / h) + 1;
Transfinite Curve {14, 15, 16} = Round((H - y2) / h) + 1;
Transfinite Curve {12, 13} = Round((y2 - y1) / h) + 1;
Transfinite Surface {1:5};
Recombine Surface {1:5};

Physical Surface("plate", 11) = {1:5};

Physical Curve("bottom", 1) = {1, 2};
Physical Curve("top", 2)    = {7, 8};
Physical Curve("notch", 3)  = {3, 5, 12};
