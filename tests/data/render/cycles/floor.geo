// The floor of cycles_bracket.toml: a 40 x 40 square, z up, two triangles, 0.01 below the bracket's base.
Point(1) = {-20, -20, -0.01, 100};
Point(2) = {20, -20, -0.01, 100};
Point(3) = {20, 20, -0.01, 100};
Point(4) = {-20, 20, -0.01, 100};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 2;
Transfinite Surface{1};
Physical Surface("Floor") = {1};
Mesh.MshFileVersion = 4.1;
