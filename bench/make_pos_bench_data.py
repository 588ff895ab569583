#!/usr/bin/python3
"""Writes the files bench/pos_load_bench.cpp reads (bench/data/, git-ignored): a square plate of
2 n^2 triangles meshed by gmsh (n = 707: 999,698 triangles, 501,264 nodes) carrying one scalar step,
s = sin(6 x) cos(5 y), in the two forms gmsh writes it, both ASCII and both by gmsh's API:
    plate_nodedata.msh: MSH 4.1 ASCII, the mesh and the field as $NodeData (gmsh.view.addModelData);
    plate_mesh.msh:     the same mesh alone (what the $NodeData costs on top of it);
    plate_elementnodedata.msh: the mesh and the field at every triangle's corners as
                        $ElementNodeData (what GetDP's -v2 output holds), 3 values per triangle;
    plate.pos:          the field as a list-based view, one ST(...){...} per triangle with its corners'
                        coordinates and values (gmsh.view.addListData), as GetDP writes results.
Usage: /usr/bin/python3 bench/make_pos_bench_data.py [OUT_FOLDER=bench/data] [N=707]"""
import os
import sys

import gmsh
import numpy as np


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 707
    os.makedirs(out, exist_ok=True)
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("plate")
    gmsh.model.occ.addRectangle(0, 0, 0, 1, 1)
    gmsh.model.occ.synchronize()
    for _, curve in gmsh.model.getEntities(1):
        gmsh.model.mesh.setTransfiniteCurve(curve, n + 1)
    gmsh.model.mesh.setTransfiniteSurface(1)
    gmsh.model.mesh.generate(2)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    coords = np.asarray(coords).reshape(-1, 3)
    values = np.sin(6 * coords[:, 0]) * np.cos(5 * coords[:, 1])
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.option.setNumber("Mesh.Binary", 0)
    gmsh.write(os.path.join(out, "plate_mesh.msh"))

    node_view = gmsh.view.add("s")
    gmsh.view.addModelData(node_view, 0, "plate", "NodeData", tags, values.reshape(-1, 1), numComponents=1)
    gmsh.write(os.path.join(out, "plate_nodedata.msh"))
    gmsh.option.setNumber("PostProcessing.SaveMesh", 0)  # the mesh is in the file already
    gmsh.view.write(node_view, os.path.join(out, "plate_nodedata.msh"), append=True)

    # One ST per triangle: its corners' x, then y, then z (gmsh's list layout), then their values.
    triangle_tags, triangle_nodes = gmsh.model.mesh.getElementsByType(2)
    index = np.empty(int(tags.max()) + 1, dtype=np.int64)
    index[tags] = np.arange(len(tags))
    corners = index[np.asarray(triangle_nodes, dtype=np.int64)].reshape(-1, 3)
    data = np.concatenate([coords[corners, 0], coords[corners, 1], coords[corners, 2], values[corners]], axis=1)
    element_view = gmsh.view.add("s")
    gmsh.view.addModelData(element_view, 0, "plate", "ElementNodeData", triangle_tags, values[corners],
                           numComponents=1)
    gmsh.option.setNumber("PostProcessing.SaveMesh", 1)
    gmsh.write(os.path.join(out, "plate_elementnodedata.msh"))
    gmsh.option.setNumber("PostProcessing.SaveMesh", 0)
    gmsh.view.write(element_view, os.path.join(out, "plate_elementnodedata.msh"), append=True)

    list_view = gmsh.view.add("s")
    gmsh.view.addListData(list_view, "ST", corners.shape[0], data.ravel())
    gmsh.view.write(list_view, os.path.join(out, "plate.pos"))
    print("%d triangles, %d nodes" % (corners.shape[0], len(tags)))
    gmsh.finalize()


if __name__ == "__main__":
    main()
