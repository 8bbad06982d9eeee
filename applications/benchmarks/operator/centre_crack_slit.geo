// centre_crack_slit.geo -- FE reference for the centre crack of tests/scenes/sif_center_crack_strip.prm:
// the strip [-0.5, 0.5] x [-1.5, 1.5] with the crack (-a, 0) -- (a, 0), a = 0.2107, as a real slit
// (a thin diamond of half-width 1e-5 at x = 0 whose ends are the tips), P1 triangles of 1 mm at the
// tips growing to 50 mm. run.sh meshes it with gmsh -clscale 2, 1, 0.5 (2, 1 and 0.5 mm at the tips).
W = 0.5; H = 1.5; a = 0.2107; e = 1e-5; hf = 0.05; ht = 0.001;
Point(1) = {-W, -H, 0, hf}; Point(2) = {W, -H, 0, hf}; Point(3) = {W, H, 0, hf}; Point(4) = {-W, H, 0, hf};
Point(5) = {-a, 0, 0, ht}; Point(6) = {0, -e, 0, hf}; Point(7) = {a, 0, 0, ht}; Point(8) = {0, e, 0, hf};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
// Size: ht within 5 mm of the tips, growing to hf at 0.3; 5 mm along the slit faces.
Field[1] = Distance; Field[1].PointsList = {5, 7};
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = ht; Field[2].SizeMax = hf;
Field[2].DistMin = 0.005; Field[2].DistMax = 0.3;
Field[3] = Distance; Field[3].CurvesList = {5, 6, 7, 8}; Field[3].NumPointsPerCurve = 200;
Field[4] = Threshold; Field[4].InField = 3; Field[4].SizeMin = 0.005; Field[4].SizeMax = hf;
Field[4].DistMin = 0.01; Field[4].DistMax = 0.3;
Field[5] = Min; Field[5].FieldsList = {2, 4};
Background Field = 5;
Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromPoints = 0; Mesh.MeshSizeFromCurvature = 0;
Physical Surface("fe", 12) = {1};
Physical Curve("left", 1) = {4};
Physical Curve("right", 2) = {2};
Physical Curve("bottom", 3) = {1};
Physical Curve("top", 4) = {3};
