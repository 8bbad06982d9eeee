// inclined_crack_slit.geo -- FE reference for the inclined central crack of
// applications/examples/inclined_crack (meshes/inclined_crack.geo): the square plate [-0.5, 0.5]^2 with
// the crack of length 2a = 40 mm through the centre at beta degrees to the x axis, as a real slit (a
// thin diamond of half-width 1e-5 at the centre whose ends are the tips), P1 triangles of 0.25 mm at
// the tips growing to 50 mm at the edges. run.sh sets beta (sed on the line "beta = 30;") and meshes it
// with gmsh -clscale 2, 1, 0.5 (0.5, 0.25 and 0.125 mm at the tips).
beta = 30;
L = 0.5; a = 0.02; e = 1e-5; hf = 0.05; ht = 0.00025;
c = Cos(beta * Pi / 180); s = Sin(beta * Pi / 180);
Point(1) = {-L, -L, 0, hf}; Point(2) = {L, -L, 0, hf}; Point(3) = {L, L, 0, hf}; Point(4) = {-L, L, 0, hf};
Point(5) = {-a * c, -a * s, 0, ht}; Point(6) = {e * s, -e * c, 0, hf};
Point(7) = {a * c, a * s, 0, ht};   Point(8) = {-e * s, e * c, 0, hf};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
// Size: ht within 1 mm of the tips, growing to hf at 0.2; 1 mm along the slit faces.
Field[1] = Distance; Field[1].PointsList = {5, 7};
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = ht; Field[2].SizeMax = hf;
Field[2].DistMin = 0.001; Field[2].DistMax = 0.2;
Field[3] = Distance; Field[3].CurvesList = {5, 6, 7, 8}; Field[3].NumPointsPerCurve = 200;
Field[4] = Threshold; Field[4].InField = 3; Field[4].SizeMin = 0.001; Field[4].SizeMax = hf;
Field[4].DistMin = 0.002; Field[4].DistMax = 0.2;
Field[5] = Min; Field[5].FieldsList = {2, 4};
Background Field = 5;
Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromPoints = 0; Mesh.MeshSizeFromCurvature = 0;
Physical Surface("fe", 12) = {1};
Physical Curve("left", 1) = {4};
Physical Curve("right", 2) = {2};
Physical Curve("bottom", 3) = {1};
Physical Curve("top", 4) = {3};
