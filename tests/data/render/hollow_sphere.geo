// Cavity fixture: a hollow sphere (outer radius 1, inner 0.5, centre at the origin) meshed in
// tetrahedra and saved as one physical volume, so its skin is an outer shell and an inner shell that
// must face into the cavity (tests/mesh/shell_cavity_test.cpp, tests/render/clip_cavity_test.cpp).
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1.0};
Sphere(2) = {0, 0, 0, 0.5};
BooleanDifference(3) = {Volume{1}; Delete;}{Volume{2}; Delete;};
Physical Volume("Shell") = {3};
Mesh.MeshSizeMax = 0.3;
