// About 10K triangles: the bracket of bracket_shape.geo at element size h (mm).
h = 3.8;
Include "bracket_shape.geo";
