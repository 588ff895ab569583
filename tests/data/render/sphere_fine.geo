// A fine unit sphere for the analytic shading test: Phong-interpolated normals on this mesh must
// match the exact sphere's lighting to a few 1/255 everywhere but the silhouette.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Physical Surface("ball") = {1};
Mesh.MeshSizeMax = 0.06;
Mesh.MeshSizeMin = 0.06;
