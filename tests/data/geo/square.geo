// Unit square, 4 x 4 structured cells: 32 triangles, or 16 quads with Mesh.RecombineAll = 1.
// The top edge is periodic with the bottom one so that the files carry a $Periodic section, and the
// surface is in two physical groups so that MSH 2 writes every element twice.
Point(1) = {0, 0, 0, 1};
Point(2) = {1, 0, 0, 1};
Point(3) = {1, 1, 0, 1};
Point(4) = {0, 1, 0, 1};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve {1:4} = 5;
Transfinite Surface {1};
Periodic Curve {3} = {-1} Translate {0, 1, 0};
Physical Surface("plate") = {1};
Physical Surface("everything") = {1};
Physical Curve("rim") = {1:4};
