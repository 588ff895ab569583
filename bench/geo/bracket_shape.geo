// A machined bracket (OpenCASCADE): base plate with bolt holes, an upright web with a bore, a
// boss and a spherical knob, so the mesh has flat, cylindrical and curved regions of very
// different triangle density and lots of empty space, like the CAD parts lancer renders.
// Included by bracket_*.geo, which set the element size `h` (millimetres).
SetFactory("OpenCASCADE");

Box(1) = {0, 0, 0, 120, 80, 10};
Box(2) = {0, 30, 10, 120, 14, 70};
Cylinder(3) = {60, 25, 80, 0, 30, 0, 32};
BooleanUnion(10) = {Volume{1}; Delete;}{Volume{2}; Volume{3}; Delete;};
Sphere(11) = {100, 65, 10, 12};
Cylinder(12) = {20, 62, 10, 0, 0, 25, 9};
BooleanUnion(20) = {Volume{10}; Delete;}{Volume{11}; Volume{12}; Delete;};
Cylinder(30) = {60, 20, 80, 0, 40, 0, 18};
Cylinder(31) = {15, 12, -1, 0, 0, 12, 5};
Cylinder(32) = {105, 12, -1, 0, 0, 12, 5};
Cylinder(33) = {15, 68, -1, 0, 0, 50, 3};
Cylinder(34) = {60, 12, -1, 0, 0, 12, 7};
BooleanDifference(40) = {Volume{20}; Delete;}{Volume{30}; Volume{31}; Volume{32}; Volume{33}; Volume{34}; Delete;};

Mesh.MeshSizeMin = h;
Mesh.MeshSizeMax = h;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;  // Frontal-Delaunay: even triangles
Mesh.MshFileVersion = 4.1;
Mesh.Binary = 1;
