// glass_plate.geo -- the glass plate of the FCBM crack-branching benchmark (specs/002 §4.2) as a
// uniform grid of square cells (Peridynamics/Model = lps fft): 100 x 40 mm with a 50 mm pre-crack
// from the left edge along the mid-line y = 20 mm.
//
// The pre-crack is a band of missing grid rows (the paper's band of dead nodes, lambda = 0): the
// notch [0, a] x [H/2 - w/2, H/2 + w/2] holds no cell, so the grid rows strictly inside it have
// no node for x < a, and the nodes on its two faces are w apart. Keep w > delta (the horizon),
// so that no bond crosses the pre-crack: with h = 0.25 mm and delta = 3.985 h = 0.996 mm, w =
// 1 mm = 4 h (rows y = 19.75, 20, 20.25 mm missing).
//
// h = 0.25 mm: 400 x 160 cells, 401 x 161 grid points, 600 of them in the pre-crack: 63 200 cells
// and 63 961 nodes. Five transfinite blocks, conforming where they meet. Change h (and w) to
// refine; a, w and the block edges must be whole multiples of h.
//
// Regions (material id = tag):    plate (11).
// Boundaries (boundary id = tag): bottom (1) y = 0, top (2) y = H, crack (3) the pre-crack's
//                                 faces and tip, left (4) x = 0, right (5) x = L.

h = 0.25e-3;    // cell size (the paper's grid 512 x 256: 0.199 x 0.164 mm)
L = 100e-3;     // width
H = 40e-3;      // height
a = 50e-3;      // pre-crack length
w = 1e-3;       // pre-crack width (> delta)

y1 = H / 2 - w / 2;
y2 = H / 2 + w / 2;

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
Line(3)  = {4, 5};    // y = y1: the pre-crack's lower face
Line(4)  = {5, 6};
Line(5)  = {7, 8};    // y = y2: the pre-crack's upper face
Line(6)  = {8, 9};
Line(7)  = {10, 11};  // y = H
Line(8)  = {11, 12};
Line(9)  = {1, 4};    // x = 0
Line(10) = {2, 5};    // x = a
Line(11) = {3, 6};    // x = L
Line(12) = {5, 8};    // x = a: the pre-crack's tip
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
Transfinite Curve {12, 13} = Round(w / h) + 1;
Transfinite Surface {1:5};
Recombine Surface {1:5};

Physical Surface("plate", 11) = {1:5};

Physical Curve("bottom", 1) = {1, 2};
Physical Curve("top", 2)    = {7, 8};
Physical Curve("crack", 3)  = {3, 5, 12};
Physical Curve("left", 4)   = {9, 14};
Physical Curve("right", 5)  = {11, 13, 16};
