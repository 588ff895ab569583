# A mesh written by gmsh.write, then a node view appended with gmsh.view.write(..., append=True), as
# gmsh's API tutorials do: the appended part repeats $MeshFormat, $Entities, $Nodes and $Elements
# before the $NodeData. With partial=1 only the left square is in a physical group, so the file
# saves only its nodes while the view (built over getNodes() of the whole model) gives values for
# the right square's nodes too, and an element view gives values for its triangles.
# Usage: /usr/bin/python3 appended_view.py OUT.msh MSH_VERSION BINARY PARTIAL
import sys

import gmsh

out, version, binary, partial = sys.argv[1], float(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.add("plates")
gmsh.model.occ.addRectangle(0, 0, 0, 1, 1, 1)
gmsh.model.occ.addRectangle(2, 0, 0, 1, 1, 2)
gmsh.model.occ.synchronize()
gmsh.model.addPhysicalGroup(2, [1] if partial else [1, 2], 5)
gmsh.model.setPhysicalName(2, 5, "plates")
gmsh.option.setNumber("Mesh.MeshSizeMax", 0.5)
gmsh.model.mesh.generate(2)
gmsh.option.setNumber("Mesh.MshFileVersion", version)
gmsh.option.setNumber("Mesh.Binary", binary)
gmsh.write(out)
tags, coords, _ = gmsh.model.mesh.getNodes()
view = gmsh.view.add("x")
gmsh.view.addModelData(view, 0, "plates", "NodeData", tags, [[x] for x in coords[0::3]])
gmsh.view.write(view, out, append=True)
if partial:  # and an element view over both squares' triangles
    types, elements, _ = gmsh.model.mesh.getElements(2)
    element_view = gmsh.view.add("element number")
    gmsh.view.addModelData(element_view, 0, "plates", "ElementData", elements[0], [[float(e)] for e in elements[0]])
    gmsh.view.write(element_view, out, append=True)
gmsh.finalize()
