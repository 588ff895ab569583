// A tall model (a 3-high tower on a base, 1.4 wide) for gmsh's prints at sizes other than its window's.
SetFactory("OpenCASCADE");
Box(1) = {-0.7, 0, -0.7, 1.4, 0.3, 1.4};
Cylinder(2) = {0, 0.3, 0, 0, 2.7, 0, 0.4};
BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Physical Surface("Body") = {Abs(Boundary{ Volume{1}; })};
Mesh.MeshSizeMax = 0.3;
Mesh.MeshSizeFromCurvature = 8;
