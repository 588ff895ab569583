// The coarse bracket (bracket_coarse.geo) drawn the CAD way, z up: the base plate in the xy plane
// and the upright along +z. The quick look must stand it up (tests/scene/up_axis_test.cpp).
SetFactory("OpenCASCADE");
Box(1) = {-1.5, -0.75, 0, 3, 1.5, 0.4};
Box(2) = {-0.4, -0.75, 0.4, 0.8, 1.5, 1.4};
BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Cylinder(10) = {-1.0, 0, -0.1, 0, 0, 0.7, 0.25};
Cylinder(11) = {1.0, 0, -0.1, 0, 0, 0.7, 0.25};
Cylinder(12) = {0, 0.9, 1.3, 0, -1.8, 0, 0.25};
BooleanDifference{ Volume{1}; Delete; }{ Volume{10, 11, 12}; Delete; }
Physical Surface("Body") = {Abs(Boundary{ Volume{1}; })};
Mesh.MeshSizeMax = 0.2;
Mesh.MeshSizeMin = 0.08;
Mesh.MeshSizeFromCurvature = 8;
