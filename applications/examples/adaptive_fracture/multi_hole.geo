// multi_hole.geo -- case 4 of Hu et al. (specs/003 §5.1): the plate
// [0, 0.065] x [0, 0.12] with four holes on a lattice of spacing dx
// (lattice.geo): two loading holes on the left (radius 6.5 mm, upper and
// lower), a middle hole (radius 6 mm) and a larger hole (radius 10 mm).
//
// THE HOLE CENTRES ARE ASSUMED. The paper gives them only in its Fig. 15,
// which we do not have. The plate (65 x 120 mm, loading holes of 13 mm
// diameter, a 20 mm hole) is the drilled plate of Bittencourt et al. (1996);
// its layout is used here (mm, from the lower left corner): loading holes
// (20, 25) and (20, 95), larger hole (36.5, 51), and the middle hole at
// (10, 65), where that specimen's notch tip is. A user with the figure
// changes the centres and radii below; nothing else depends on them.
//
// The loading holes hold pins: the cells whose centre is within the hole's
// radius r but farther than r - 3 dx from its centre, a ring 3 dx thick (the
// fictitious layer of the paper, like the grips of case 2), stay in the mesh
// and are bonded to the plate; the cells within r - 3 dx are left out. On a
// lattice coarser than r / 3 the ring is the whole disc.
//
// Physical groups: surfaces plate (11), pin_lower_cells (12) and
// pin_upper_cells (13); node sets (physical points, user_guide.md "Boundary
// conditions") pin_lower (1) and pin_upper (2): every lattice point of the
// pin's cells, its ring and the hole's edge, the nodes a Dirichlet condition
// moves. A file that sets dx and then includes this one gets another lattice
// (tests/meshes/multi_hole_coarse.geo).

If (!Exists(dx))
  dx = 0.001;
EndIf
W = 0.065; // plate width (x)
H = 0.12;  // plate height (y)

// ---- the holes (assumed positions; see above)
r_load   = 0.0065;  // loading holes
x_load   = 0.020;
y_lower  = 0.025;   // lower loading hole
y_upper  = 0.095;   // upper loading hole
r_mid    = 0.006;   // middle hole
x_mid    = 0.010;
y_mid    = 0.065;
r_large  = 0.010;   // larger hole
x_large  = 0.0365;
y_large  = 0.051;
pin      = 3;       // pin ring thickness in cells

nx = Round(W / dx);
ny = Round(H / dx);
x0 = 0;
y0 = 0;

// kind[j nx + i]: 0 left out, 1 plate, 2 lower pin, 3 upper pin
keep[] = {};
kind[] = {};
For j In {0 : ny - 1}
  For i In {0 : nx - 1}
    xc = x0 + (i + 0.5) * dx;
    yc = y0 + (j + 0.5) * dx;
    dl = Sqrt((xc - x_load) ^ 2 + (yc - y_lower) ^ 2);
    du = Sqrt((xc - x_load) ^ 2 + (yc - y_upper) ^ 2);
    dm = Sqrt((xc - x_mid) ^ 2 + (yc - y_mid) ^ 2);
    db = Sqrt((xc - x_large) ^ 2 + (yc - y_large) ^ 2);
    k  = 0;
    If (dl > r_load && du > r_load && dm > r_mid && db > r_large)
      k = 1;
    EndIf
    If (dl <= r_load && dl > r_load - pin * dx)
      k = 2;
    EndIf
    If (du <= r_load && du > r_load - pin * dx)
      k = 3;
    EndIf
    kind[j * nx + i] = k;
    keep[j * nx + i] = k > 0;
  EndFor
EndFor

Include "lattice.geo";

// The surfaces of lattice.geo are numbered in the order of the cells kept.
plate[]     = {};
pin_lower[] = {};
pin_upper[] = {};
s = 0;
For j In {0 : ny - 1}
  For i In {0 : nx - 1}
    If (kind[j * nx + i] > 0)
      s += 1;
      If (kind[j * nx + i] == 1)
        plate[] += s;
      EndIf
      If (kind[j * nx + i] == 2)
        pin_lower[] += s;
      EndIf
      If (kind[j * nx + i] == 3)
        pin_upper[] += s;
      EndIf
    EndIf
  EndFor
EndFor

// The pins' nodes: the lattice points (i, j) with a pin cell among their four
// cells (i - 1 .. i, j - 1 .. j). Point tag 1 + j (nx + 1) + i (lattice.geo).
nodes_lower[] = {};
nodes_upper[] = {};
For j In {0 : ny}
  For i In {0 : nx}
    in_lower = 0;
    in_upper = 0;
    For jj In {j - 1 : j}
      For ii In {i - 1 : i}
        If (ii >= 0 && ii < nx && jj >= 0 && jj < ny)
          If (kind[jj * nx + ii] == 2)
            in_lower = 1;
          EndIf
          If (kind[jj * nx + ii] == 3)
            in_upper = 1;
          EndIf
        EndIf
      EndFor
    EndFor
    If (in_lower)
      nodes_lower[] += 1 + j * (nx + 1) + i;
    EndIf
    If (in_upper)
      nodes_upper[] += 1 + j * (nx + 1) + i;
    EndIf
  EndFor
EndFor

Physical Surface("plate", 11)           = plate[];
Physical Surface("pin_lower_cells", 12) = pin_lower[];
Physical Surface("pin_upper_cells", 13) = pin_upper[];
Physical Point("pin_lower", 1)          = nodes_lower[];
Physical Point("pin_upper", 2)          = nodes_upper[];
