// glass_plate_paper_grid.geo -- the glass plate of glass_plate.geo on the FCBM paper's grid
// (specs/002 §4.2): 503 x 245 grid points of spacing hx = 100/502 mm = 0.1992 mm and hy = 40/244
// mm = 0.1639 mm (the paper: 0.199 x 0.164 mm in a 512 x 256 box; lps fft's box, the smallest
// 2-3-5-7 sizes that leave a gap of more than a horizon, is 512 x 252). The pre-crack: the grid
// rows strictly inside [0, a] x [H/2 - w/2, H/2 + w/2] missing, a = 50 mm = 251 hx, w = 8 hy =
// 1.311 mm (> delta = 1 mm, so that no bond crosses it). With Peridynamics/Horizon factor = 5.534
// the horizon is 5.534 sqrt(hx hy) = 1.000 mm (lps fft's horizon is m times the cells' size
// V^(1/2)). 120 480 cells, 121 478 nodes.

L  = 100e-3;
H  = 40e-3;
hx = L / 502;
hy = H / 244;
a  = 251 * hx;  // 50 mm
w  = 8 * hy;

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

Transfinite Curve {1, 3, 5, 7} = Round(a / hx) + 1;
Transfinite Curve {2, 4, 6, 8} = Round((L - a) / hx) + 1;
Transfinite Curve {9, 10, 11} = Round(y1 / hy) + 1;
Transfinite Curve {14, 15, 16} = Round((H - y2) / hy) + 1;
Transfinite Curve {12, 13} = Round(w / hy) + 1;
Transfinite Surface {1:5};
Recombine Surface {1:5};

Physical Surface("plate", 11) = {1:5};

Physical Curve("bottom", 1) = {1, 2};
Physical Curve("top", 2)    = {7, 8};
Physical Curve("crack", 3)  = {3, 5, 12};
Physical Curve("left", 4)   = {9, 14};
Physical Curve("right", 5)  = {11, 13, 16};
