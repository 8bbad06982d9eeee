// cracked_strip_mixed.geo -- meshes/cracked_strip.geo with its FE blocks in
// triangles and its PD band in quadrilaterals: a mesh of two kinds of cell.
fe_triangles = 1;
Include "../../meshes/cracked_strip.geo";
