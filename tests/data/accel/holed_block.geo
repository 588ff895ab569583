// Accelerator fixture: a block with a through bore and a boss (OpenCASCADE), triangles only,
// about 2500 faces: curved and axis-aligned planar regions, many vertices on shared planes.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 4, 3, 2};
Cylinder(2) = {2, 1.5, -1, 0, 0, 4, 0.8};
Cylinder(3) = {0.7, 0.7, 2, 0, 0, 1, 0.4};
BooleanDifference(4) = {Volume{1}; Delete;}{Volume{2}; Delete;};
BooleanUnion(5) = {Volume{4}; Delete;}{Volume{3}; Delete;};
Mesh.MeshSizeMin = 0.25;
Mesh.MeshSizeMax = 0.25;
Mesh.Algorithm = 6;
Mesh.MshFileVersion = 4.1;
Mesh.Binary = 1;
