// three_point_bending.geo -- case 3 of Hu et al. (specs/003 §5.1): the beam
// [0, 0.24] x [0, 0.06] with a central notch from the bottom edge, 0.3 w =
// 18 mm long and 2 dx wide, on a lattice of spacing dx (lattice.geo). Three
// pads 3 dx thick and 4 dx wide carry the loads: two supports below the
// beam, centred 0.105 m either side of the middle (span 0.21 m), and the
// load pad on top in the middle.
//
// Boundaries (boundary id = tag): support_left (1) and support_right (2),
// the lower edges of the support pads; load (3), the upper edge of the load
// pad.

If (!Exists(dx))
  dx = 0.0012;
EndIf
L     = 0.24;
W     = 0.06;
notch = 0.3 * W;
pad   = 4;   // pad width in cells
nx    = Round(L / dx);
ny    = Round(W / dx) + 6;
x0    = 0;
y0    = -3 * dx;
mid   = nx / 2;                    // the middle lattice line
sl    = Round((L / 2 - 0.105) / dx); // the left support's centre line
sr    = Round((L / 2 + 0.105) / dx);

keep[] = {};
For j In {0 : ny - 1}
  For i In {0 : nx - 1}
    xc = x0 + (i + 0.5) * dx;
    yc = y0 + (j + 0.5) * dx;
    in_beam  = yc > 0 && yc < W && !(Fabs(xc - L / 2) < dx && yc < notch);
    in_below = yc < 0 && (Fabs(i + 0.5 - sl) < pad / 2 || Fabs(i + 0.5 - sr) < pad / 2);
    in_above = yc > W && Fabs(i + 0.5 - mid) < pad / 2;
    keep[j * nx + i] = in_beam || in_below || in_above;
  EndFor
EndFor

Include "lattice.geo";

Physical Surface("beam", 11)        = body[];
Physical Curve("support_left", 1)  = {1 + sl - pad / 2 : sl + pad / 2};
Physical Curve("support_right", 2) = {1 + sr - pad / 2 : sr + pad / 2};
Physical Curve("load", 3)          = {1 + ny * nx + mid - pad / 2 : ny * nx + mid + pad / 2};
