// cube_sphere.geo without physical groups: gmsh then saves every element (points, lines, the
// surfaces, the tetrahedra), and the two volumes are told apart by their elementary entities.
SetFactory("OpenCASCADE");
Box(1) = {-1, -1, -1, 2, 2, 2};
Sphere(2) = {0, 0, 0, 0.6};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Mesh.MeshSizeFromCurvature = 36;
Mesh.MeshSizeMax = 0.5;
