// A slab of glass (y in [0, 1]) on a slab of water (y in [-1, 0]), x and z in [-2, 2], meshed
// together: the plane y = 0 is their interface, and its rim meets the skin on edges of three faces.
SetFactory("OpenCASCADE");
Box(1) = {-2, 0, -2, 4, 1, 4};
Box(2) = {-2, -1, -2, 4, 1, 4};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Physical Volume("Glass") = {1};
Physical Volume("Water") = {2};
Mesh.MeshSizeMax = 1.0;
