// Clipped-volume golden: a sleeve (tube with a radial cross hole) around a separate shaft, meshed
// in tetrahedra and saved with the two physical volumes only, so lancer renders each volume's skin
// and caps each cut in its group's material. Axis along y, bottom at y = 0.
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 1.2, 0, 1.0};
Cylinder(2) = {0, -0.1, 0, 0, 1.4, 0, 0.6};
Cylinder(3) = {-1.2, 0.6, 0, 2.4, 0, 0, 0.22};
BooleanDifference(4) = {Volume{1}; Delete;}{Volume{2, 3}; Delete;};
Cylinder(5) = {0, 0, 0, 0, 1.8, 0, 0.42};
Physical Volume("Sleeve") = {4};
Physical Volume("Shaft") = {5};
Mesh.MeshSizeMax = 0.17;
Mesh.MeshSizeMin = 0.05;
