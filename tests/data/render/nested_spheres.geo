// Two concentric sphere surfaces (radii 1 and 0.5) in different physical groups, like a steel ball
// inside a glass ball: each is a solid of its own and faces outward (tests/mesh/shell_cavity_test.cpp).
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1.0};
Sphere(2) = {0, 0, 0, 0.5};
Physical Surface("Glass") = {1};
Physical Surface("Steel") = {2};
Mesh.MeshSizeMax = 0.3;
