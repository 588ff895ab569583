#!/usr/bin/env python3
"""Regenerates the $ElementNodeData fixtures of tests/data/element_node/ with the real gmsh (its
Python API, Debian's python3-gmsh; run with /usr/bin/python3).

tet_v{22,41}_{ascii,bin}.msh: a unit cube of tetrahedra (lancer draws their skin) with
  "f"     $NodeData, f = x + 2y + 3z;
  "g"     $ElementNodeData of the same f at every element's nodes, steps 0 and 1 (times 0 and 0.5,
          values f and 2f): drawn, it must be f's picture;
  "jump"  $ElementNodeData, each element's tag % 5 at all its nodes (a field that jumps between
          elements, as B or a stress does), and "jumpe", the same as $ElementData;
  "u"     $ElementNodeData of a linear displacement (0.1 x, 0.2 y, 0) for warps and arrows.
fuzz/corpus/msh_reader/fields_element_node_{v22_ascii,v41_bin}.msh: the cube in a few tetrahedra
  with "g" only, seeds for the .msh fuzzer (under 8 KB).
quad9_v41_bin.msh: the unit square of second-order (9-node) quadrangles and 6-node triangles,
  "f" ($NodeData) and "g" ($ElementNodeData, all nine or six nodes) of x + 2y.
"""
import os
import sys

import gmsh

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
OUT = os.path.join(ROOT, "tests", "data", "element_node")
FUZZ = os.path.join(ROOT, "fuzz", "corpus", "msh_reader")


def f_of(x, y, z):
    return x + 2 * y + 3 * z


def node_coordinates():
    tags, coords, _ = gmsh.model.mesh.getNodes()
    return {int(t): coords[3 * i:3 * i + 3] for i, t in enumerate(tags)}


def element_blocks(dim):
    types, elements, nodes = gmsh.model.mesh.getElements(dim)
    for etype, etags, enodes in zip(types, elements, nodes):
        per = len(enodes) // len(etags)
        for i, tag in enumerate(etags):
            yield int(tag), [int(n) for n in enodes[per * i:per * (i + 1)]]


def add_views(model, dim, with_volume_views):
    xyz = node_coordinates()
    node_tags = sorted(xyz)
    views = []
    f = gmsh.view.add("f")
    gmsh.view.addModelData(f, 0, model, "NodeData", node_tags, [[f_of(*xyz[n])] for n in node_tags])
    views.append(f)
    elements = list(element_blocks(dim))
    tags = [t for t, _ in elements]
    g = gmsh.view.add("g")
    for step, scale in ((0, 1.0), (1, 2.0)):
        gmsh.view.addModelData(g, step, model, "ElementNodeData", tags,
                               [[scale * f_of(*xyz[n]) for n in nodes] for _, nodes in elements],
                               time=0.5 * step)
    views.append(g)
    if with_volume_views:
        jump = gmsh.view.add("jump")
        gmsh.view.addModelData(jump, 0, model, "ElementNodeData", tags,
                               [[float(t % 5)] * len(nodes) for t, nodes in elements])
        jumpe = gmsh.view.add("jumpe")
        gmsh.view.addModelData(jumpe, 0, model, "ElementData", tags, [[float(t % 5)] for t, _ in elements])
        u = gmsh.view.add("u")
        data = []
        for _, nodes in elements:
            values = []
            for n in nodes:
                x, y, _z = xyz[n]
                values += [0.1 * x, 0.2 * y, 0.0]
            data.append(values)
        gmsh.view.addModelData(u, 0, model, "ElementNodeData", tags, data, numComponents=3)
        views += [jump, jumpe, u]
    return views


def write(path, views, version, binary):
    gmsh.option.setNumber("Mesh.MshFileVersion", version)
    gmsh.option.setNumber("Mesh.Binary", binary)
    gmsh.option.setNumber("PostProcessing.SaveMesh", 0)
    gmsh.write(path)
    for v in views:
        gmsh.view.write(v, path, append=True)


def tet_cube():
    gmsh.model.add("cube")
    gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
    gmsh.model.occ.synchronize()
    gmsh.model.addPhysicalGroup(3, [1], 1)
    gmsh.option.setNumber("Mesh.MeshSizeMin", 0.5)
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.5)
    gmsh.model.mesh.generate(3)
    views = add_views("cube", 3, True)
    for version in (2.2, 4.1):
        for binary in (0, 1):
            name = "tet_v{}_{}.msh".format(str(version).replace(".", ""), "bin" if binary else "ascii")
            write(os.path.join(OUT, name), views, version, binary)
    for v in views:
        gmsh.view.remove(v)


def tiny_cube():
    gmsh.model.add("tiny")
    gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
    gmsh.model.occ.synchronize()
    gmsh.model.addPhysicalGroup(3, [1], 1)
    gmsh.option.setNumber("Mesh.MeshSizeMin", 2)
    gmsh.option.setNumber("Mesh.MeshSizeMax", 2)
    gmsh.model.mesh.generate(3)
    xyz = node_coordinates()
    elements = list(element_blocks(3))
    g = gmsh.view.add("g")
    gmsh.view.addModelData(g, 0, "tiny", "ElementNodeData", [t for t, _ in elements],
                           [[f_of(*xyz[n]) for n in nodes] for _, nodes in elements])
    write(os.path.join(FUZZ, "fields_element_node_v22_ascii.msh"), [g], 2.2, 0)
    write(os.path.join(FUZZ, "fields_element_node_v41_bin.msh"), [g], 4.1, 1)
    gmsh.view.remove(g)


def quad9_square():
    gmsh.model.add("square")
    gmsh.model.occ.addRectangle(0, 0, 0, 1, 1)
    gmsh.model.occ.addRectangle(1, 0, 0, 1, 1)
    gmsh.model.occ.fragment([(2, 1)], [(2, 2)])
    gmsh.model.occ.synchronize()
    gmsh.model.addPhysicalGroup(2, [1, 2], 1)
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.3)
    gmsh.model.mesh.setRecombine(2, 1)  # quads on the left square, triangles on the right one
    gmsh.model.mesh.generate(2)
    gmsh.model.mesh.setOrder(2)
    views = add_views("square", 2, False)
    write(os.path.join(OUT, "quad9_v41_bin.msh"), views, 4.1, 1)


def main():
    os.makedirs(OUT, exist_ok=True)
    gmsh.initialize(["gmsh", "-v", "0"])
    tet_cube()
    tiny_cube()
    quad9_square()
    gmsh.finalize()


if __name__ == "__main__":
    sys.exit(main())
