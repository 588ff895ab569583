// The example's glass block: a 1.6 x 0.8 x 0.8 box of quads (a thick slab that shifts what is seen
// through it), resting on the floor at y = -1.
SetFactory("OpenCASCADE");
Box(1) = {-0.8, -1, -0.4, 1.6, 0.8, 0.8};
Transfinite Curve {:} = 3;
Transfinite Surface {:};
Recombine Surface {:};
Physical Surface("block") = {1:6};
