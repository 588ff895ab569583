// A machined bracket: a base plate with two through holes and an upright with a bore. Each face
// family is its own physical group (Body, Holes, Bore), so the quick look colours them apart and
// scene files can give them their own materials.
SetFactory("OpenCASCADE");
Box(1) = {-1.5, 0, -0.75, 3, 0.4, 1.5};
Box(2) = {-0.4, 0.4, -0.75, 0.8, 1.4, 1.5};
BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Cylinder(10) = {-1.0, -0.1, 0, 0, 0.7, 0, 0.25};
Cylinder(11) = {1.0, -0.1, 0, 0, 0.7, 0, 0.25};
Cylinder(12) = {0, 1.3, -0.9, 0, 0, 1.8, 0.25};
BooleanDifference{ Volume{1}; Delete; }{ Volume{10, 11, 12}; Delete; }
all() = Abs(Boundary{ Volume{1}; });
holes() = Surface In BoundingBox{-1.3, -0.2, -0.3, -0.7, 0.7, 0.3};
holes() += Surface In BoundingBox{0.7, -0.2, -0.3, 1.3, 0.7, 0.3};
bore() = Surface In BoundingBox{-0.3, 1.0, -0.8, 0.3, 1.6, 0.8};
body() = all();
body() -= holes();
body() -= bore();
Physical Surface("Body") = {body()};
Physical Surface("Holes") = {holes()};
Physical Surface("Bore") = {bore()};
Mesh.MeshSizeMax = 0.06;
Mesh.MeshSizeMin = 0.02;
Mesh.MeshSizeFromCurvature = 24;
