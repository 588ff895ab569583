// About one million triangles on a unit sphere, for bench/msh_load_vs_gmsh.sh (unstructured, so the
// node numbering is as irregular as a real part's).
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Mesh.Algorithm = 5;  // Delaunay: the fastest 2D mesher for a mesh this size
If (!Exists(size))  // gmsh -setnumber size S makes a coarser sphere for a quick check
  size = 0.0054;
EndIf
Mesh.MeshSizeMin = size;
Mesh.MeshSizeMax = size;
Physical Surface("sphere") = {1};
