// edge_crack_slit.geo -- FE reference for the edge crack of tests/scenes/sif_edge_crack_strip.prm:
// the strip [-0.5, 0.5] x [-1.5, 1.5] with an edge slit of width 2e-5 from (-0.5, 0) to the tip
// (-0.1893, 0), P1 triangles of 1 mm at the tip. Run by run.sh.
W=0.5; H=1.5; a=0.3107; e=1e-5; hf=0.05; ht=0.001;
xt = -W + a;
Point(1) = {-W,-H,0,hf}; Point(2) = {W,-H,0,hf}; Point(3) = {W,H,0,hf}; Point(4) = {-W,H,0,hf};
Point(5) = {-W,e,0,hf}; Point(6) = {xt,0,0,ht}; Point(7) = {-W,-e,0,hf};
Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,5}; Line(5) = {5,6}; Line(6) = {6,7}; Line(7) = {7,1};
Curve Loop(1) = {1,2,3,4,5,6,7};
Plane Surface(1) = {1};
Field[1] = Distance; Field[1].PointsList = {6};
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = ht; Field[2].SizeMax = hf; Field[2].DistMin = 0.005; Field[2].DistMax = 0.3;
Field[3] = Distance; Field[3].CurvesList = {5,6};
Field[4] = Threshold; Field[4].InField = 3; Field[4].SizeMin = 0.005; Field[4].SizeMax = hf; Field[4].DistMin = 0.01; Field[4].DistMax = 0.3;
Field[5] = Min; Field[5].FieldsList = {2,4};
Background Field = 5;
Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromPoints = 0;
Physical Surface("fe", 12) = {1};
Physical Curve("bottom", 3) = {1};
Physical Curve("top", 4) = {3};
