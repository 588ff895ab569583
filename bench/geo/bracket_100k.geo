// About 100K triangles: the bracket of bracket_shape.geo at element size h (mm).
h = 1.13;
Include "bracket_shape.geo";
