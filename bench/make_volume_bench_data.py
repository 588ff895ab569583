#!/usr/bin/python3
"""Writes the volume that the benchmarks of slices, isosurfaces and field lines read (bench/data/,
git-ignored): a slice against a render without it, an isosurface of about a million triangles against
a BVH build over it, 1,000 field lines of 1,000 steps. The unit box, meshed by gmsh's default 3D
Delaunay with one size H everywhere (H = 0.0166: 1,014,275 tetrahedra, 174,754 nodes), is saved as
binary MSH 4.1 with two node fields written by gmsh's API (gmsh.view.addModelData, appended to the
mesh with gmsh.view.write):
    s  a scalar, the gyroid sin(k x) cos(k y) + sin(k y) cos(k z) + sin(k z) cos(k x), k = 2 pi n,
       with n = round(0.3 / H) periods across the box (18 at the default size): a period of about 3.3
       mesh sizes makes the isosurface s = 0 a dense, triply periodic sheet of about 1.3 triangles per
       tetrahedron (the script prints how many, counted from the sign of s at the corners: one for a
       tetrahedron with one or three corners above zero, two for two).
    b  a vector whose field lines, from any start within R = 0.5 of the box's vertical axis
       (x = y = 0.5), stay in the box: they wind around the axis on nested tori, the level sets of
       psi = sin(pi rho / R) sin(pi z), rho the distance to the axis (b = the rotation about the axis
       + (dpsi/dz, -dpsi/drho) in the (rho, z) plane); beyond rho = R, the rotation alone.
File: volume_box.msh, 55 MB at the default size, whose isosurface s = 0 has 1,333,742 triangles.
Meshing takes about 45 s of one CPU (gmsh 4.8, one thread).
Usage: /usr/bin/python3 bench/make_volume_bench_data.py [OUT_FOLDER=bench/data] [H=0.0166]
       (a larger H for a quick try: H = 0.05 gives 36,842 tetrahedra in about a second)"""
import math
import os
import sys
import time

import gmsh
import numpy as np

TORUS_RADIUS = 0.5


def gyroid(points, periods):
    x, y, z = (2 * math.pi * periods * points[:, i] for i in range(3))
    return np.sin(x) * np.cos(y) + np.sin(y) * np.cos(z) + np.sin(z) * np.cos(x)


def winding_field(points):
    dx, dy, z = points[:, 0] - 0.5, points[:, 1] - 0.5, points[:, 2]
    rho = np.hypot(dx, dy)
    inside = rho < TORUS_RADIUS
    # psi = sin(pi rho / R) sin(pi z); the poloidal part (dpsi/dz, -dpsi/drho) is tangent to its
    # level sets, so the lines never leave the torus they start on.
    radial = np.where(inside, math.pi * np.sin(math.pi * rho / TORUS_RADIUS) * np.cos(math.pi * z), 0.0)
    vertical = np.where(inside, -math.pi / TORUS_RADIUS * np.cos(math.pi * rho / TORUS_RADIUS) * np.sin(math.pi * z),
                        0.0)
    safe_rho = np.where(rho > 0, rho, 1.0)
    cos_phi, sin_phi = np.where(rho > 0, dx / safe_rho, 0.0), np.where(rho > 0, dy / safe_rho, 0.0)
    return np.stack([-dy + radial * cos_phi, dx + radial * sin_phi, vertical], axis=1)


def isosurface_triangles(tetrahedra_rows, values):
    above = (values[tetrahedra_rows] > 0).sum(axis=1)
    return int(np.count_nonzero((above == 1) | (above == 3)) + 2 * np.count_nonzero(above == 2))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")
    size = float(sys.argv[2]) if len(sys.argv) > 2 else 0.0166
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, "volume_box.msh")
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("General.NumThreads", 1)
    gmsh.option.setNumber("Mesh.RandomSeed", 1)
    gmsh.model.add("volume_box")
    gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
    gmsh.model.occ.synchronize()
    gmsh.model.addPhysicalGroup(3, [1], 1)
    gmsh.model.setPhysicalName(3, 1, "box")
    gmsh.model.addPhysicalGroup(2, [tag for _, tag in gmsh.model.getEntities(2)], 2)
    gmsh.model.setPhysicalName(2, 2, "skin")
    gmsh.option.setNumber("Mesh.MeshSizeMin", size)
    gmsh.option.setNumber("Mesh.MeshSizeMax", size)
    started = time.process_time()
    gmsh.model.mesh.generate(3)
    meshing_seconds = time.process_time() - started

    node_tags, coords, _ = gmsh.model.mesh.getNodes()
    points = np.asarray(coords).reshape(-1, 3)
    scalar = gyroid(points, max(1, round(0.3 / size)))
    tetrahedron_tags, tetrahedron_nodes = gmsh.model.mesh.getElementsByType(4)
    row_of_node = np.empty(int(node_tags.max()) + 1, dtype=np.int64)
    row_of_node[node_tags] = np.arange(len(node_tags))
    tetrahedra_rows = row_of_node[np.asarray(tetrahedron_nodes, dtype=np.int64)].reshape(-1, 4)

    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.option.setNumber("Mesh.Binary", 1)
    gmsh.write(path)
    gmsh.option.setNumber("PostProcessing.SaveMesh", 0)  # the mesh is in the file already
    for name, values in (("s", scalar.reshape(-1, 1)), ("b", winding_field(points))):
        view = gmsh.view.add(name)
        gmsh.view.addModelData(view, 0, "volume_box", "NodeData", node_tags, values, numComponents=values.shape[1])
        gmsh.view.write(view, path, append=True)
    gmsh.finalize()
    print(f"{path}: {len(tetrahedron_tags)} tetrahedra, {len(node_tags)} nodes, fields s (scalar) and b (vector), "
          f"{os.path.getsize(path) / 1e6:.1f} MB; meshing {meshing_seconds:.1f} s CPU; "
          f"isosurface s = 0: {isosurface_triangles(tetrahedra_rows, scalar)} triangles")


if __name__ == "__main__":
    main()
