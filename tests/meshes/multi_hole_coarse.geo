// multi_hole_coarse.geo -- the multi-hole plate of
// applications/examples/adaptive_fracture (case 4 of Hu et al., assumed hole
// centres) on a lattice of 5 mm (for tests): 13 x 24 cells; the pins fill
// their loading holes (the 3 dx ring is wider than the radius).
dx = 0.005;
Include "../../applications/examples/adaptive_fracture/multi_hole.geo";
