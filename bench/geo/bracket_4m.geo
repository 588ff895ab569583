// About 4M triangles: the bracket of bracket_shape.geo at element size h (mm).
h = 0.179;
Include "bracket_shape.geo";
