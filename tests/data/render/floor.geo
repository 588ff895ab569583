// A square floor of quads at y = -1 (transfinite, recombined): shadows and quads in the golden images.
Point(1) = {-3, -1, -3, 1};
Point(2) = {3, -1, -3, 1};
Point(3) = {3, -1, 3, 1};
Point(4) = {-3, -1, 3, 1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {4, 3, 2, 1};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 9;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("Floor") = {1};
