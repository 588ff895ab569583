// A floor of quads (transfinite + recombined) to put parts on.
Point(1) = {-4, 0, -4, 1};
Point(2) = {4, 0, -4, 1};
Point(3) = {4, 0, 4, 1};
Point(4) = {-4, 0, 4, 1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {4, 3, 2, 1};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 17;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("Floor") = {1};
