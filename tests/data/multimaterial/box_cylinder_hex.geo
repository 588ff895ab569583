// Hexahedra of two physical volumes: a square [-1, 1]^2 holding a disc of radius 0.6, meshed in
// quads and extruded along z from -1 to 1 in layers, so the column of hexahedra (and the prisms
// that recombination leaves, if any) shares the cylinder's side with the box around it.
SetFactory("OpenCASCADE");
Rectangle(1) = {-1, -1, -1, 2, 2};
Disk(2) = {0, 0, -1, 0.6};
BooleanFragments{ Surface{1}; Delete; }{ Surface{2}; Delete; }
Mesh.MeshSizeFromCurvature = 40;
Mesh.MeshSizeMax = 0.3;
Recombine Surface{:};
box[] = Extrude {0, 0, 2} { Surface{3}; Layers{6}; Recombine; };
column[] = Extrude {0, 0, 2} { Surface{2}; Layers{6}; Recombine; };
Physical Volume("Box") = {box[1]};
Physical Volume("Cylinder") = {column[1]};
