// A unit square with a Physical Curve on its outline and a Physical Surface: meshed with -1 (as a
// new user might, like gmsh t1.geo -1) the file holds only the outline's lines, nothing to draw.
Point(1) = {0, 0, 0, 0.25};
Point(2) = {1, 0, 0, 0.25};
Point(3) = {1, 1, 0, 0.25};
Point(4) = {0, 1, 0, 0.25};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("outline") = {1:4};
Physical Surface("plate") = {1};
