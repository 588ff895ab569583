// A wide model (4 x 1 x 0.8, two holes through it) for gmsh's prints at sizes other than its window's.
SetFactory("OpenCASCADE");
Box(1) = {-2, -0.5, -0.4, 4, 1, 0.8};
Cylinder(2) = {-1.2, 0, -0.5, 0, 0, 1, 0.3};
Cylinder(3) = {1.2, 0, -0.5, 0, 0, 1, 0.3};
BooleanDifference{ Volume{1}; Delete; }{ Volume{2, 3}; Delete; }
Physical Surface("Body") = {Abs(Boundary{ Volume{1}; })};
Mesh.MeshSizeMax = 0.3;
Mesh.MeshSizeFromCurvature = 8;
