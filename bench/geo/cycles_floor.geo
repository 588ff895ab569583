// The floor under the bracket for the Cycles comparison (bench/cycles/*.toml): a 3 m square (mm, like
// bracket_shape.geo), two triangles, 0.2 mm below the base plate so no face of the part lies in it.
Point(1) = {-1440, -1460, -0.2, 1e4};
Point(2) = {1560, -1460, -0.2, 1e4};
Point(3) = {1560, 1540, -0.2, 1e4};
Point(4) = {-1440, 1540, -0.2, 1e4};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 2;
Transfinite Surface{1};
Physical Surface("Floor") = {1};
Mesh.MshFileVersion = 4.1;
