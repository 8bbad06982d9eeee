// patch_2d_quad_pins.geo -- patch_2d_quad.geo with a node set: the physical point group "pins"
// (tag 5) holds the two bottom corners of the PD slab, (-0.2, -0.5) and (0.2, -0.5).
Include "patch_2d_quad.geo";
Physical Point("pins", 5) = {2, 3};
