// A 1 x 2 plate at survey-like coordinates (x = 1e6, y = -2e6): tests the recentring to float.
Point(1) = {1e6, -2e6, 5, 1};
Point(2) = {1e6 + 1, -2e6, 5, 1};
Point(3) = {1e6 + 1, -2e6 + 2, 5, 1};
Point(4) = {1e6, -2e6 + 2, 5, 1};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve {1, 3} = 5;
Transfinite Curve {2, 4} = 9;
Transfinite Surface {1};
Physical Surface("far") = {1};
