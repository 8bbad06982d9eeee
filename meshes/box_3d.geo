// 3D box [-0.5,0.5] x [-0.5,0.5] x [-0.25,0.25] m of structured hexahedra,
// the same as PDLSM-FEM's "box" example: a PD slab |x| <= 0.2 (40 % of the
// volume) between two FE blocks. h = 0.025 gives 40 x 40 x 20 = 32 000 cells,
// 35 301 nodes, 105 903 DoFs.
h = 0.025;
nx_fe = Round(0.3 / h); nx_pd = Round(0.4 / h);
ny = Round(1.0 / h); nz = Round(0.5 / h);

Point(1) = {-0.5, -0.5, -0.25};
// Three blocks along x, extruded from one edge each so that they conform.
Point(2) = {-0.2, -0.5, -0.25};
Point(3) = { 0.2, -0.5, -0.25};
Point(4) = { 0.5, -0.5, -0.25};
Line(1) = {1, 2}; Transfinite Curve{1} = nx_fe + 1;
Line(2) = {2, 3}; Transfinite Curve{2} = nx_pd + 1;
Line(3) = {3, 4}; Transfinite Curve{3} = nx_fe + 1;
s[] = Extrude {0, 1, 0} { Curve{1, 2, 3}; Layers{ny}; Recombine; };
v[] = Extrude {0, 0, 0.5} { Surface{s[1], s[5], s[9]}; Layers{nz}; Recombine; };
Coherence;

eps = 1e-6;
Physical Volume("fe", 12) = {v[1], v[13]};
Physical Volume("pd", 11) = {v[7]};
Physical Surface("left", 1)   = Surface In BoundingBox{-0.5-eps, -1, -1, -0.5+eps, 1, 1};
Physical Surface("right", 2)  = Surface In BoundingBox{ 0.5-eps, -1, -1,  0.5+eps, 1, 1};
Physical Surface("bottom", 3) = Surface In BoundingBox{-1, -0.5-eps, -1, 1, -0.5+eps, 1};
Physical Surface("top", 4)    = Surface In BoundingBox{-1,  0.5-eps, -1, 1,  0.5+eps, 1};
Physical Surface("back", 5)   = Surface In BoundingBox{-1, -1, -0.25-eps, 1, 1, -0.25+eps};
Physical Surface("front", 6)  = Surface In BoundingBox{-1, -1,  0.25-eps, 1, 1,  0.25+eps};
