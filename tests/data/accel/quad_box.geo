// Accelerator fixture: the unit cube meshed with structured quads (transfinite + recombine),
// 12 x 12 per side, so quads are primitives and every vertex sits on a regular lattice of planes.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 13;
Transfinite Surface{1};
Recombine Surface{1};
Extrude {0, 0, 1} { Surface{1}; Layers{12}; Recombine; }
Mesh.MshFileVersion = 4.1;
Mesh.Binary = 0;
