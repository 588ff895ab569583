// A unit box in three slabs along x, meshed with every linear volume element type: hexahedra
// (x < 0.4, extruded from a transfinite quad face), tetrahedra with pyramids on the quad face they
// share with the hexahedra (0.4 < x < 0.7, unstructured), prisms (x > 0.7, extruded from the
// tetrahedra's triangle face).
General.NumThreads = 1;
Mesh.RandomSeed = 1;
h = 0.1;
Point(1) = {0, 0, 0, h};
Point(2) = {0, 1, 0, h};
Point(3) = {0, 1, 1, h};
Point(4) = {0, 0, 1, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 11;
Transfinite Surface{1};
Recombine Surface{1};
hexes[] = Extrude{0.4, 0, 0}{ Surface{1}; Layers{4}; Recombine; };
tets[] = Extrude{0.3, 0, 0}{ Surface{hexes[0]}; };
prisms[] = Extrude{0.3, 0, 0}{ Surface{tets[0]}; Layers{3}; Recombine; };
// The base of an extrusion keeps its normal, along the extrusion, into the box: turn it outward.
ReverseMesh Surface{1};
Physical Volume("hexahedra", 1) = {hexes[1]};
Physical Volume("tetrahedra", 2) = {tets[1]};
Physical Volume("prisms", 3) = {prisms[1]};
Physical Surface("boundary", 10) = {1, hexes[{2:5}], tets[{2:5}], prisms[0], prisms[{2:5}]};
