// Hexahedra of two physical volumes: a square [-1, 1]^2 holding a disc of radius 0.6, meshed in
// quads and extruded along z from -1 to 1 in layers (built-in kernel, so that both extrusions share
// the cylinder's side): a column of hexahedra inside a box of hexahedra.
lc = 0.2;
Point(1) = {0, 0, -1, lc};
Point(2) = {0.6, 0, -1, lc};
Point(3) = {0, 0.6, -1, lc};
Point(4) = {-0.6, 0, -1, lc};
Point(5) = {0, -0.6, -1, lc};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Point(6) = {-1, -1, -1, 0.3};
Point(7) = {1, -1, -1, 0.3};
Point(8) = {1, 1, -1, 0.3};
Point(9) = {-1, 1, -1, 0.3};
Line(5) = {6, 7};
Line(6) = {7, 8};
Line(7) = {8, 9};
Line(8) = {9, 6};
Curve Loop(1) = {5, 6, 7, 8};
Curve Loop(2) = {1, 2, 3, 4};
Plane Surface(1) = {1, 2};
Plane Surface(2) = {2};
Recombine Surface{1, 2};
extruded[] = Extrude {0, 0, 2} { Surface{1, 2}; Layers{6}; Recombine; };
Physical Volume("Box") = {1};
Physical Volume("Cylinder") = {2};
