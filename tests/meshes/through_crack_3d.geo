// through_crack_3d.geo -- the plate of through_crack_plate.geo extruded to a slab
// 0 <= z <= t of nz layers of hexahedra: the same in-plane mesh in every layer, so
// that a 3D run with u_z = 0 on both faces is the 2D plane-strain run of
// through_crack_2d.geo.
//
// Regions (material id = tag):    pd (11) the box, fe (12) the rest.
// Boundaries (boundary id = tag): left (1), right (2), bottom (3), top (4),
//                                 back (5) z = 0, front (6) z = t.
Include "through_crack_plate.geo";

nz = 3;        // layers through the thickness
t  = nz * h;   // thickness

frame[] = Extrude {0, 0, t} { Surface{1}; Layers{nz}; Recombine; };
box[]   = Extrude {0, 0, t} { Surface{2}; Layers{nz}; Recombine; };

Physical Volume("pd", 11) = {box[1]};
Physical Volume("fe", 12) = {frame[1]};

e = 1e-6;
Physical Surface("left", 1)   = Surface In BoundingBox {-L-e, -H-e, -e, -L+e,  H+e, t+e};
Physical Surface("right", 2)  = Surface In BoundingBox { L-e, -H-e, -e,  L+e,  H+e, t+e};
Physical Surface("bottom", 3) = Surface In BoundingBox {-L-e, -H-e, -e,  L+e, -H+e, t+e};
Physical Surface("top", 4)    = Surface In BoundingBox {-L-e,  H-e, -e,  L+e,  H+e, t+e};
Physical Surface("back", 5)   = Surface In BoundingBox {-L-e, -H-e, -e,  L+e,  H+e, e};
Physical Surface("front", 6)  = Surface In BoundingBox {-L-e, -H-e, t-e,  L+e,  H+e, t+e};
