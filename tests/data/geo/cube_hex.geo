// Unit cube of 3 x 3 x 3 structured hexahedra (27), volume physical group only: the skin is 54 quads.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Transfinite Curve {:} = 4;
Transfinite Surface {:};
Transfinite Volume {:};
Recombine Surface {:};
Mesh.RecombineAll = 1;
Physical Volume("block") = {1};
