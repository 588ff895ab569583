// Sphere of radius 1: a closed, outward-oriented triangle shell of area close to 4 pi.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Mesh.MeshSizeMax = 0.3;
Physical Surface("ball") = {1};
