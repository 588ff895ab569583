// Two unit squares side by side. "left" holds the left one, "both" holds both, and "right_flipped"
// takes the right one with reversed orientation (gmsh writes its tag negated, -3, in MSH 4.1's
// $Entities, and the copy's nodes reversed in MSH 2). So the left square is in two groups and the
// right one in two: tests check that a face is in all of its groups, that -3 is the group 3, and
// that a scene's most specific group mapping wins.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 1, 1};
Rectangle(2) = {2, 0, 0, 1, 1};
Physical Surface("left", 1) = {1};
Physical Surface("both", 2) = {1, 2};
Physical Surface("right_flipped", 3) = {-2};
Mesh.MeshSizeMin = 0.5;
Mesh.MeshSizeMax = 0.5;
