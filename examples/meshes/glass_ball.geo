// The example's balls (mirror, glass, red): a unit sphere, closed shell oriented outward by lancer.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Physical Surface("ball") = {1};
Mesh.MeshSizeMax = 0.12;
Mesh.MeshSizeMin = 0.12;
