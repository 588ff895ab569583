// A unit cube whose surface is in two named physical groups; the STL writer makes a solid of each.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Physical Surface("bottom") = {5};
Physical Surface("walls") = {1, 2, 3, 4, 6};
Mesh.MeshSizeMin = 0.4;
Mesh.MeshSizeMax = 0.4;
Mesh.StlOneSolidPerSurface = 2;
