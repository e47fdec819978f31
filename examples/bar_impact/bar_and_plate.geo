// Section 6.3 of the paper: a steel bar 100 x 10 x 10 mm whose end x = 100 mm is 1 um away
// from a plate 2 x 14 x 14 mm (the bar centred on it; the gap lets the initial velocity tell
// the bodies' nodes apart, and closes at 1 m/s in 1 us). Two bodies of one mesh that share no
// vertex. Coarse hexahedra of 2 mm;
// the parameter files refine once to the paper's 1 mm.
// Boundary ids (physical surfaces): 10 the bar's impact end, 11 the plate's face under it,
// 1 the plate's back face (x = 102.001 mm, the support), 12 the rest of the bar, 13 the rest of
// the plate.
//   gmsh -3 -format msh22 bar_and_plate.geo -o bar_and_plate.msh
h = 0.002;
// The bar: a point extruded along x, y and z in layers of 2 mm.
Point(1) = {0, 0.002, 0.002};
bar_x[] = Extrude {0.1, 0, 0} { Point{1}; Layers{50}; };
bar_y[] = Extrude {0, 0.01, 0} { Line{bar_x[1]}; Layers{5}; Recombine; };
bar_z[] = Extrude {0, 0, 0.01} { Surface{bar_y[1]}; Layers{5}; Recombine; };
// The plate, in one layer of 2 mm.
g = 1e-6;
Point(100) = {0.1 + g, 0, 0};
plate_x[] = Extrude {0.002, 0, 0} { Point{100}; Layers{1}; };
plate_y[] = Extrude {0, 0.014, 0} { Line{plate_x[1]}; Layers{7}; Recombine; };
plate_z[] = Extrude {0, 0, 0.014} { Surface{plate_y[1]}; Layers{7}; Recombine; };
e = 1e-7;
impact[]  = Surface In BoundingBox {0.1 - e, 0.002 - e, 0.002 - e, 0.1 + e, 0.012 + e, 0.012 + e};
front[]   = Surface In BoundingBox {0.1 + g - e, -e, -e, 0.1 + g + e, 0.014 + e, 0.014 + e};
back[]    = Surface In BoundingBox {0.102 + g - e, -e, -e, 0.102 + g + e, 0.014 + e, 0.014 + e};
bar_all[] = Surface In BoundingBox {-e, 0.002 - e, 0.002 - e, 0.1 + e, 0.012 + e, 0.012 + e};
all[]     = Surface In BoundingBox {-e, -e, -e, 0.102 + g + e, 0.014 + e, 0.014 + e};
front[] -= impact[];
bar_rest[] = bar_all[];
bar_rest[] -= impact[];
plate_rest[] = all[];
plate_rest[] -= bar_all[];
plate_rest[] -= front[];
plate_rest[] -= back[];
Physical Surface(10) = {impact[]};
Physical Surface(11) = {front[]};
Physical Surface(1)  = {back[]};
Physical Surface(12) = {bar_rest[]};
Physical Surface(13) = {plate_rest[]};
Physical Volume(0) = {bar_z[1], plate_z[1]};
