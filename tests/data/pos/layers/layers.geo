// Two dielectric layers stacked in a unit cube: "lower" (z < 0.5, epsr 1) and "upper" (z > 0.5,
// epsr 3), the bottom face at v = 0, the top face at v = 1, the sides insulated. Coarse on purpose:
// a few dozen tetrahedra keep GetDP's .pos views a few KB.
SetFactory("OpenCASCADE");
General.NumThreads = 1;
Mesh.RandomSeed = 1;
Box(1) = {0, 0, 0, 1, 1, 0.5};
Box(2) = {0, 0, 0.5, 1, 1, 0.5};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
eps = 1e-3;
bottom() = Surface In BoundingBox{-eps, -eps, -eps, 1 + eps, 1 + eps, eps};
middle() = Surface In BoundingBox{-eps, -eps, 0.5 - eps, 1 + eps, 1 + eps, 0.5 + eps};
top() = Surface In BoundingBox{-eps, -eps, 1 - eps, 1 + eps, 1 + eps, 1 + eps};
Physical Volume("lower", 1) = {1};
Physical Volume("upper", 2) = {2};
Physical Surface("bottom", 11) = {bottom()};
Physical Surface("top", 12) = {top()};
Physical Surface("interface", 13) = {middle()};
Mesh.MeshSizeMin = 1;
Mesh.MeshSizeMax = 1;
