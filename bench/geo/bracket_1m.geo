// About 1M triangles: the bracket of bracket_shape.geo at element size h (mm).
h = 0.358;
Include "bracket_shape.geo";
