// through_crack_2d.geo -- the plate of through_crack_plate.geo in 2D.
//
// Regions (material id = tag):    pd (11) the box, fe (12) the rest.
// Boundaries (boundary id = tag): left (1), right (2), bottom (3), top (4).
Include "through_crack_plate.geo";

Physical Surface("pd", 11) = {2};
Physical Surface("fe", 12) = {1};
Physical Curve("left", 1)   = {4};
Physical Curve("right", 2)  = {2};
Physical Curve("bottom", 3) = {1};
Physical Curve("top", 4)    = {3};
