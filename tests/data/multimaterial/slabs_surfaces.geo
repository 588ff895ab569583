// glass_water_slabs.geo as surfaces only (meshed -2): each slab's boundary a Physical Surface, so
// the shared wall, in both groups, is drawn once and its rim edges meet three faces. lancer finds
// the two regions from the order of the faces around those edges and caps each in its group.
SetFactory("OpenCASCADE");
Box(1) = {-2, 0, -2, 4, 1, 4};
Box(2) = {-2, -1, -2, 4, 1, 4};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Physical Surface("Glass") = Boundary{ Volume{1}; };
Physical Surface("Water") = Boundary{ Volume{2}; };
Mesh.MeshSizeMax = 1.0;
