// A parallel-plate capacitor in a grounded air box: two 1 x 1 x 0.05 plates, 0.4 apart, centred in a
// 3 x 3 x 3 box. Only the air is meshed (the plates are holes); the mesh is fine near the plates.
SetFactory("OpenCASCADE");
General.NumThreads = 1;
Mesh.RandomSeed = 1;
Box(1) = {-1.5, -1.5, -1.5, 3, 3, 3};
Box(2) = {-0.5, -0.5, 0.2, 1, 1, 0.05};
Box(3) = {-0.5, -0.5, -0.25, 1, 1, 0.05};
air() = BooleanDifference{ Volume{1}; Delete; }{ Volume{2, 3}; Delete; };
eps = 1e-3;
top() = Surface In BoundingBox{-0.5 - eps, -0.5 - eps, 0.2 - eps, 0.5 + eps, 0.5 + eps, 0.25 + eps};
bottom() = Surface In BoundingBox{-0.5 - eps, -0.5 - eps, -0.25 - eps, 0.5 + eps, 0.5 + eps, -0.2 + eps};
outer() = Abs(Boundary{ Volume{air()}; });
outer() -= {top(), bottom()};
Physical Volume("air", 1) = {air()};
Physical Surface("plate_top", 11) = {top()};
Physical Surface("plate_bottom", 12) = {bottom()};
Physical Surface("box", 13) = {outer()};

// Sizes that keep the mesh with GetDP's v and e (as $ElementNodeData) under 600 KB: about 2,000 tetrahedra.
DefineConstant[ h_plate = 0.15, h_box = 1.5 ];
Field[1] = Distance;
Field[1].FacesList = {top(), bottom()};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_plate;
Field[2].SizeMax = h_box;
Field[2].DistMin = 0.05;
Field[2].DistMax = 1.2;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
