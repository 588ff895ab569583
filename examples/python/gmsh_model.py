"""A part modelled and meshed with the gmsh API and rendered by lancer straight from memory: no mesh
file is written, and no display is needed (gmsh's own picture export needs an OpenGL window).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/gmsh_model.py [OUT.png]
"""

import sys

import gmsh

import lancer

out = sys.argv[1] if len(sys.argv) > 1 else "gmsh_model.png"

gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.add("flange")
# A flange: a disc with a hub, a bore and four bolt holes (OpenCASCADE booleans).
disc = gmsh.model.occ.addCylinder(0, 0, 0, 0, 0, 0.3, 2.0)
hub = gmsh.model.occ.addCylinder(0, 0, 0.3, 0, 0, 0.9, 1.0)
body, _ = gmsh.model.occ.fuse([(3, disc)], [(3, hub)])
holes = [(3, gmsh.model.occ.addCylinder(0, 0, -0.1, 0, 0, 1.5, 0.6))]
for x, y in [(1.5, 0), (-1.5, 0), (0, 1.5), (0, -1.5)]:
    holes.append((3, gmsh.model.occ.addCylinder(x, y, -0.1, 0, 0, 0.5, 0.2)))
part, _ = gmsh.model.occ.cut(body, holes)
gmsh.model.occ.synchronize()
# Physical surfaces: the faces of the bolt holes in one group, the rest in another (one colour each).
holes_faces, other_faces = [], []
for _, surface in gmsh.model.getBoundary(part, oriented=False):
    xmin, ymin, _, xmax, ymax, _ = gmsh.model.getBoundingBox(2, surface)
    small = max(xmax - xmin, ymax - ymin) < 0.5
    (holes_faces if small else other_faces).append(surface)
gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, other_faces), "flange")
gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, holes_faces), "bolt holes")
gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 24)
gmsh.option.setNumber("Mesh.MeshSizeMax", 0.15)
gmsh.model.mesh.generate(2)

mesh = lancer.from_gmsh(dim=2)  # the surfaces gmsh meshed, with their physical groups
gmsh.finalize()

scene = lancer.Scene.quick_look(mesh, up="z")
image = lancer.render(scene, width=640, height=480, samples=4, edges=True)
image.save(out)
print(f"{mesh}: {image.shape[1]}x{image.shape[0]} in {image.stats['seconds']:.2f} s -> {out}")
