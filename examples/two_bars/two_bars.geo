// Two strips 50 x 4 mm (fe/two_bars_contact, fe/particles_against_fe_faces, the PD against FE
// example): a striker [0, 50] mm and a target
// [50.001, 100.001] mm (a gap of 1 um, so that the initial velocity tells their nodes apart),
// each of 50 x 2 quadrilaterals of 1 x 2 mm.
// Boundary ids: 10 the striker's end x = 50 mm, 11 the target's end x = 50.001 mm, 12 the
// rest of the striker, 13 the rest of the target.
//   gmsh -2 -format msh22 two_bars.geo -o two_bars.msh
g = 1e-6;
e = 1e-7;
Point(1) = {0, 0, 0};
striker_x[] = Extrude {0.05, 0, 0} { Point{1}; Layers{50}; };
striker[] = Extrude {0, 0.004, 0} { Line{striker_x[1]}; Layers{2}; Recombine; };
Point(100) = {0.05 + g, 0, 0};
target_x[] = Extrude {0.05, 0, 0} { Point{100}; Layers{50}; };
target[] = Extrude {0, 0.004, 0} { Line{target_x[1]}; Layers{2}; Recombine; };
striker_end[] = Curve In BoundingBox {0.05 - e, -e, -e, 0.05 + e, 0.004 + e, e};
target_end[] = Curve In BoundingBox {0.05 + g - e, -e, -e, 0.05 + g + e, 0.004 + e, e};
striker_all[] = Curve In BoundingBox {-e, -e, -e, 0.05 + e, 0.004 + e, e};
target_all[] = Curve In BoundingBox {0.05 + g - e, -e, -e, 0.1 + g + e, 0.004 + e, e};
striker_all[] -= striker_end[];
target_all[] -= target_end[];
Physical Curve(10) = {striker_end[]};
Physical Curve(11) = {target_end[]};
Physical Curve(12) = {striker_all[]};
Physical Curve(13) = {target_all[]};
Physical Surface(0) = {striker[1], target[1]};
