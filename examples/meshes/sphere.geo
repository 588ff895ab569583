// A unit sphere for the quick examples (gmsh OpenCASCADE kernel).
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Physical Surface("Sphere") = {1};
Mesh.MeshSizeMax = 0.08;
Mesh.MeshSizeMin = 0.08;
