// three_point_bending_coarse.geo -- case 3's beam (applications/examples/
// adaptive_fracture/three_point_bending.geo) on a 4 mm lattice (60 x 15
// cells of the beam, 1 017 nodes): the scene of the case-3 stability chart
// (stability.sh with SCENE=three_point_bending_coarse.prm).
dx = 0.004;
Include "../../examples/adaptive_fracture/three_point_bending.geo";
