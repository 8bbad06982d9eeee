// multi_hole_2_5mm.geo -- the multi-hole plate of applications/examples/adaptive_fracture
// (case 4 of Hu et al., assumed hole centres) on a lattice of 2.5 mm (26 x 48 cells).
dx = 0.0025;
Include "../../examples/adaptive_fracture/multi_hole.geo";
