#!/usr/bin/python3
# Builds tests/data/render/terrain.msh with gmsh's Python API: a terrain height field like a survey
# STL re-saved by gmsh (one discrete surface of triangles, no geometry): 4000 x 3000 units, z up,
# heights 4 to 124 (64 + 60 sin(x/450) cos(y/380)) on a 40 x 30 grid, two triangles per cell.
# The shadow-acne test lights it from straight above, where a height field cannot shadow itself.
# Run by scripts/make_render_fixtures.sh: terrain.py OUTPUT.msh
import math
import sys

import gmsh

NX, NY = 40, 30
gmsh.initialize(["-noenv"])
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.add("terrain")
surface = gmsh.model.addDiscreteEntity(2)
tags, coords = [], []
for i in range(NX + 1):
    for j in range(NY + 1):
        x, y = 4000.0 * i / NX, 3000.0 * j / NY
        tags.append(1 + i * (NY + 1) + j)
        coords += [x, y, 64 + 60 * math.sin(x / 450) * math.cos(y / 380)]
gmsh.model.mesh.addNodes(2, surface, tags, coords)
triangles = []
for i in range(NX):
    for j in range(NY):
        p00 = 1 + i * (NY + 1) + j
        p10 = p00 + NY + 1
        triangles += [p00, p10, p10 + 1, p00, p10 + 1, p00 + 1]
gmsh.model.mesh.addElementsByType(surface, 2, [], triangles)
gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, [surface]), "Terrain")
gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
gmsh.option.setNumber("Mesh.Binary", 1)
gmsh.write(sys.argv[1])
gmsh.finalize()
