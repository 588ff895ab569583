// About one million triangles on a unit sphere, for bench/msh_load_vs_gmsh.sh (unstructured, so the
// node numbering is as irregular as a real part's).
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Mesh.Algorithm = 5;  // Delaunay: the fastest 2D mesher for a mesh this size
Mesh.MeshSizeMin = 0.0054;
Mesh.MeshSizeMax = 0.0054;
Physical Surface("sphere") = {1};
