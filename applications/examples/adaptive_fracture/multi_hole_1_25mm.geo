// multi_hole_1_25mm.geo -- multi_hole.geo on a lattice of 1.25 mm (52 x 96
// cells, 4 896 nodes): the lattice of the picture in README.md ("Case 4").
dx = 0.00125;
Include "multi_hole.geo";
