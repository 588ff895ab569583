// A unit box whose only physical group is a volume. Meshed with -2, gmsh saves no element (only the
// elements of physical groups, and the volume has none in 2D): MSH 4.1 holds $Entities alone, MSH 2
// empty $Nodes and $Elements. lancer says to mesh it with -3.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Physical Volume("solid", 7) = {1};
