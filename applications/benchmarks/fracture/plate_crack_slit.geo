// plate_crack_slit.geo -- reference for the plateCrack K_I: a pure FE model of the same square
// plate [-0.5, 0.5]^2 with the centre crack (0, -0.098) -- (0, 0.098) as a real slit of
// width 2e-5 (a thin diamond whose ends are the tips), P1 triangles of 0.5 mm at the tips
// growing to 20 mm. Run by run.sh (with -clscale 1 and 0.5).
L = 0.5; a = 0.098; e = 1e-5; hf = 0.02; ht = 0.0005;
Point(1) = {-L, -L, 0, hf}; Point(2) = {L, -L, 0, hf}; Point(3) = {L, L, 0, hf};
Point(4) = {-L, L, 0, hf};  Point(5) = {-L, 0, 0, hf};
Point(6) = {0, -a, 0, ht};  Point(7) = {e, 0, 0, 0.004}; Point(8) = {0, a, 0, ht};
Point(9) = {-e, 0, 0, 0.004};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 1};
Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 9}; Line(9) = {9, 6};
Curve Loop(1) = {1, 2, 3, 4, 5};
Curve Loop(2) = {6, 7, 8, 9};
Plane Surface(1) = {1, 2};
Field[1] = Distance; Field[1].PointsList = {6, 8};
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = ht; Field[2].SizeMax = hf;
Field[2].DistMin = 0.002; Field[2].DistMax = 0.15;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromPoints = 0;
Physical Surface("fe", 12) = {1};
Physical Curve("left", 1) = {4, 5};
Physical Curve("right", 2) = {2};
