// three_point_bending_2_4mm.geo -- three_point_bending.geo on a lattice of
// 2.4 mm (2 663 nodes): the lattice of the picture in README.md ("Case 3")
// and of the case-3 timing in doc/benchmarks/adaptive.md.
dx = 0.0024;
Include "three_point_bending.geo";
