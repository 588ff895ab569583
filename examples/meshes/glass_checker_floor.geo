// The example's checkerboard floor: 10 x 10 unit squares at y = -1 (built-in kernel: predictable tags),
// each square 2 x 2 quads; physical groups "Dark" and "Light" alternate so a scene can colour them.
n = 10;
h = -1;
For i In {0:n}
  For j In {0:n}
    Point(i * (n + 1) + j + 1) = {i - n / 2, h, j - n / 2};
  EndFor
EndFor
// Lines along x: (i, j) -> (i + 1, j); lines along z: (i, j) -> (i, j + 1).
For i In {0:n - 1}
  For j In {0:n}
    Line(i * (n + 1) + j + 1) = {i * (n + 1) + j + 1, (i + 1) * (n + 1) + j + 1};
  EndFor
EndFor
zBase = n * (n + 1);
For i In {0:n}
  For j In {0:n - 1}
    Line(zBase + i * n + j + 1) = {i * (n + 1) + j + 1, i * (n + 1) + j + 2};
  EndFor
EndFor
dark[] = {};
light[] = {};
For i In {0:n - 1}
  For j In {0:n - 1}
    s = i * n + j + 1;
    Curve Loop(s) = {i * (n + 1) + j + 1, zBase + (i + 1) * n + j + 1, -(i * (n + 1) + j + 2), -(zBase + i * n + j + 1)};
    Plane Surface(s) = {s};
    If ((i + j) % 2 == 0)
      dark[] += {s};
    Else
      light[] += {s};
    EndIf
  EndFor
EndFor
Transfinite Curve{:} = 3;
Transfinite Surface{:};
Recombine Surface{:};
Physical Surface("Dark") = {dark[]};
Physical Surface("Light") = {light[]};
