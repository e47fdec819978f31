// A plate with a central hole for PeriArlequin (Geometry/Mesh file): 100 mm x 50 mm, hole of
// radius 6 mm at the centre, unstructured quadrilaterals (recombined triangles) of about
// 4.5 mm. The PD region of the case, [35, 65] x [10, 40] mm around the hole, is a surface of
// its own, so that cell faces follow its edges (PeriArlequin requires it). Physical lines
// become boundary ids: 0 left (x = 0), 1 right (x = 0.1), 2 bottom, 3 top, 4 the hole.
//   gmsh -2 -format msh22 plate_with_hole.geo -o plate_with_hole.msh
lc = 4.5e-3;
r  = 6e-3;
Point(1) = {0, 0, 0, lc};
Point(2) = {0.1, 0, 0, lc};
Point(3) = {0.1, 0.05, 0, lc};
Point(4) = {0, 0.05, 0, lc};
Point(5) = {0.05, 0.025, 0, lc};
Point(6) = {0.05 + r, 0.025, 0, lc};
Point(7) = {0.05, 0.025 + r, 0, lc};
Point(8) = {0.05 - r, 0.025, 0, lc};
Point(9) = {0.05, 0.025 - r, 0, lc};
Point(10) = {0.035, 0.01, 0, lc};
Point(11) = {0.065, 0.01, 0, lc};
Point(12) = {0.065, 0.04, 0, lc};
Point(13) = {0.035, 0.04, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Circle(5) = {6, 5, 7};
Circle(6) = {7, 5, 8};
Circle(7) = {8, 5, 9};
Circle(8) = {9, 5, 6};
Line(9) = {10, 11};
Line(10) = {11, 12};
Line(11) = {12, 13};
Line(12) = {13, 10};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Curve Loop(3) = {9, 10, 11, 12};
Plane Surface(1) = {1, 3};
Plane Surface(2) = {3, 2};
Recombine Surface{1, 2};
Mesh.Algorithm = 6;               // frontal-Delaunay
Mesh.RecombinationAlgorithm = 1;  // Blossom
Physical Curve(0) = {4};
Physical Curve(1) = {2};
Physical Curve(2) = {1};
Physical Curve(3) = {3};
Physical Curve(4) = {5, 6, 7, 8};
Physical Surface(0) = {1, 2};
