// A 40 x 20 x 10 mm block of hexahedra for coupling/gmsh_block_3d: the x-y face meshed with
// unstructured quadrilaterals of about 6.5 mm (recombined), extruded in two layers along z
// (102 hexahedra).
// The PD box [12, 28] x [5, 15] mm is a surface of its own, so that cell faces follow it.
// Boundary ids: 0 at x = 0, 1 at x = 0.04, others untagged (free).
//   gmsh -3 -format msh22 gmsh_block_3d.geo -o gmsh_block_3d.msh
lc = 6.5e-3;
Point(1) = {0, 0, 0, lc};
Point(2) = {0.04, 0, 0, lc};
Point(3) = {0.04, 0.02, 0, lc};
Point(4) = {0, 0.02, 0, lc};
Point(5) = {0.012, 0.005, 0, lc};
Point(6) = {0.028, 0.005, 0, lc};
Point(7) = {0.028, 0.015, 0, lc};
Point(8) = {0.012, 0.015, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
Plane Surface(2) = {2};
Recombine Surface{1, 2};
Mesh.Algorithm = 6;
Mesh.RecombinationAlgorithm = 1;
out1[] = Extrude {0, 0, 0.01} { Surface{1}; Layers{2}; Recombine; };
out2[] = Extrude {0, 0, 0.01} { Surface{2}; Layers{2}; Recombine; };
// out1[]: top surface, volume, then the lateral surfaces in the order of the curve loop.
Physical Surface(0) = {out1[5]};
Physical Surface(1) = {out1[3]};
Physical Volume(0) = {out1[1], out2[1]};
