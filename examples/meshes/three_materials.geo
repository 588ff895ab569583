// Three physical volumes meshed together (examples/cut_multimaterial.toml; the golden test keeps a
// coarser copy in tests/data/multimaterial): a housing (a disc of radius 1 with a bore and a cross
// hole) around a bushing (a tube in the bore) around a shaft that stands out of both ends. Axis
// along y, housing from y = 0 to 1.
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 1, 0, 1.0};
Cylinder(2) = {0, 0, 0, 0, 1, 0, 0.6};
Cylinder(3) = {-1.2, 0.5, 0, 2.4, 0, 0, 0.18};
BooleanDifference(4) = {Volume{1}; Delete;}{Volume{2, 3}; Delete;};
Cylinder(5) = {0, 0, 0, 0, 1, 0, 0.6};
Cylinder(6) = {0, -0.3, 0, 0, 1.6, 0, 0.32};
BooleanFragments{ Volume{4, 5}; Delete; }{ Volume{6}; Delete; }
Physical Volume("Housing") = {4};
Physical Volume("Bushing") = {5};
Physical Volume("Shaft") = {6, 7, 8};
Mesh.MeshSizeMax = 0.1;
Mesh.MeshSizeMin = 0.04;
