// A coarse unit sphere for the shading golden images: facets show under flat shading, Gouraud and
// Phong must smooth them away.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Physical Surface("ball") = {1};
Mesh.MeshSizeMax = 0.3;
Mesh.MeshSizeMin = 0.3;
