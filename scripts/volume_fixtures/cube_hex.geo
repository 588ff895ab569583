// The unit cube as 6 x 6 x 6 hexahedra (extruded with layers from one corner), with its skin.
General.NumThreads = 1;
Point(1) = {0, 0, 0};
edge[] = Extrude{1, 0, 0}{ Point{1}; Layers{6}; };
face[] = Extrude{0, 1, 0}{ Curve{edge[1]}; Layers{6}; Recombine; };
cube[] = Extrude{0, 0, 1}{ Surface{face[1]}; Layers{6}; Recombine; };
// The base of an extrusion keeps its normal, along the extrusion, into the cube: turn it outward.
ReverseMesh Surface{face[1]};
Physical Volume("cube", 1) = {cube[1]};
Physical Surface("skin", 2) = {face[1], cube[0], cube[{2:5}]};
