"""A regular 8 x 8 grid of quads over the unit square (gmsh's transfinite, recombined mesh) with the
element data 3 x + y sampled at each quad's centroid: the mean of the four quads around an inner
vertex is 3 x + y there exactly, so isolines of it have a closed form.
Usage: python3 element_centroid_grid.py OUT.msh"""
import sys

import gmsh

gmsh.initialize(["-noenv"])
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.add("grid")
square = gmsh.model.occ.addRectangle(0, 0, 0, 1, 1)
gmsh.model.occ.synchronize()
for curve in gmsh.model.getEntities(1):
    gmsh.model.mesh.setTransfiniteCurve(curve[1], 9)
gmsh.model.mesh.setTransfiniteSurface(square)
gmsh.model.mesh.setRecombine(2, square)
gmsh.model.addPhysicalGroup(2, [square], 1)
gmsh.model.setPhysicalName(2, 1, "plate")
gmsh.model.mesh.generate(2)
types, tags, nodes = gmsh.model.mesh.getElements(2, square)
node_tags, coords, _ = gmsh.model.mesh.getNodes()
position = {int(t): coords[3 * i:3 * i + 3] for i, t in enumerate(node_tags)}
values = []
corners_of = [list(nodes[0][i:i + 4]) for i in range(0, len(nodes[0]), 4)]
for corners in corners_of:
    x = sum(position[int(n)][0] for n in corners) / 4
    y = sum(position[int(n)][1] for n in corners) / 4
    values.append([3 * x + y])
view = gmsh.view.add("f")
gmsh.view.addModelData(view, 0, "grid", "ElementData", [int(t) for t in tags[0]], values)
gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
gmsh.write(sys.argv[1])
gmsh.view.write(view, sys.argv[1], append=True)
gmsh.finalize()
