// square_hole_coarse.geo -- the square plate with a hole of
// applications/examples/adaptive_fracture on a lattice of 2.5 mm (for tests).
dx = 0.0025;
Include "../../applications/examples/adaptive_fracture/square_hole.geo";
