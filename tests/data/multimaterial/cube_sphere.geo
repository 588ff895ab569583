// Two physical volumes meshed together (BooleanFragments shares the sphere's surface): a ball of
// radius 0.6 inside the cube [-1, 1]^3. Tests of interfaces read it in several formats and orders
// (scripts/make_multimaterial_fixtures.sh); a cut through the centre shows the ball's exact circle.
SetFactory("OpenCASCADE");
Box(1) = {-1, -1, -1, 2, 2, 2};
Sphere(2) = {0, 0, 0, 0.6};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Physical Volume("Cube") = {3};
Physical Volume("Ball") = {2};
Mesh.MeshSizeFromCurvature = 36;
Mesh.MeshSizeMax = 0.5;
