// Unit cube of unstructured tetrahedra, saved with a volume physical group only, so the file holds
// tetrahedra and no surface triangles: lancer must render the tetrahedra's skin.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Mesh.MeshSizeMin = 0.5;
Mesh.MeshSizeMax = 0.5;
Physical Volume("solid") = {1};
