// A unit sphere for the mirror and glass balls: fine enough that refraction through it reads as a
// lens, coarse enough to keep the fixture small. Closed shell: lancer orients it outward at load.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Physical Surface("ball") = {1};
Mesh.MeshSizeMax = 0.15;
Mesh.MeshSizeMin = 0.15;
