// lattice.geo -- included by the case files of this folder: a uniform lattice
// of nx x ny square cells of side dx from (x0, y0), one quadrilateral per cell
// the case keeps. Before the Include, the case sets dx, x0, y0, nx, ny and
// keep[j nx + i] (1: keep cell (i, j), whose centre is (x0 + (i + 1/2) dx,
// y0 + (j + 1/2) dx)). After it: body[] (the cells kept), and the lattice lines
// H(i, j) = 1 + j nx + i from lattice point (i, j) to (i + 1, j) and
// V(i, j) = 1 + nh + j (nx + 1) + i from (i, j) to (i, j + 1), for the case's
// physical curves. Every PD node sits on the lattice.

Mesh.ElementOrder = 1;

For j In {0 : ny}
  For i In {0 : nx}
    Point(1 + j * (nx + 1) + i) = {x0 + i * dx, y0 + j * dx, 0};
  EndFor
EndFor
nh = nx * (ny + 1);
For j In {0 : ny}
  For i In {0 : nx - 1}
    Line(1 + j * nx + i) = {1 + j * (nx + 1) + i, 2 + j * (nx + 1) + i};
  EndFor
EndFor
For j In {0 : ny - 1}
  For i In {0 : nx}
    Line(1 + nh + j * (nx + 1) + i) = {1 + j * (nx + 1) + i,
                                       1 + (j + 1) * (nx + 1) + i};
  EndFor
EndFor
s      = 0;
body[] = {};
For j In {0 : ny - 1}
  For i In {0 : nx - 1}
    If (keep[j * nx + i])
      s += 1;
      Curve Loop(s) = {1 + j * nx + i, 2 + nh + j * (nx + 1) + i,
                       -(1 + (j + 1) * nx + i), -(1 + nh + j * (nx + 1) + i)};
      Plane Surface(s) = {s};
      body[] += s;
    EndIf
  EndFor
EndFor
Transfinite Curve {:} = 2;
Transfinite Surface {:};
Recombine Surface {:};
