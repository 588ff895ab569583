#!/usr/bin/python3
"""Writes the volume result that bench/volume_load.sh reads (bench/data/, git-ignored): a cantilever plate
[0, L] x [0, W] x [0, T] clamped at x = 0, meshed by gmsh's default 3D Delaunay with one size H everywhere,
saved as binary MSH 4.1 with the tetrahedra in the Physical Volume "plate" and the clamped face in the
Physical Surface "clamp", followed by STEPS $NodeData steps of a 3-component "displacement" (the
Euler-Bernoulli deflection w = q x^2 (6 L^2 - 4 L x + x^2) growing with time, t = step).
At the defaults (L = 8, W = 1, T = 0.02, H = 0.0062, 20 steps) the plate is about three elements thick,
so its skin is about 0.3 triangles per tetrahedron, as in a thin-walled part: about 3.2M tetrahedra,
0.95M skin triangles, 0.6M nodes, 460 MB. The mesh comes from gmsh's API; numpy writes the steps'
bytes directly (the layout gmsh.view.write gives them: int tag, 3 doubles), as gmsh's API would take
minutes to pass 20 x 0.6M vectors through Python lists. Meshing takes a few minutes of one CPU.
Usage: /usr/bin/python3 bench/make_volume_load_data.py [OUT_FOLDER=bench/data] [H=0.0062] [STEPS=20]
       (H = 0.02 gives about 100K tetrahedra in seconds)"""
import os
import sys
import time

import gmsh
import numpy as np

LENGTH, WIDTH, THICKNESS = 8.0, 1.0, 0.02


def node_data(tags, displacement, step):
    record = np.zeros(len(tags), dtype=[("tag", np.int32), ("v", np.float64, 3)])
    record["tag"] = tags
    record["v"] = displacement
    text = f'$NodeData\n1\n"displacement"\n1\n{float(step)}\n3\n{step}\n3\n{len(tags)}\n'.encode()
    return text + record.tobytes() + b"\n$EndNodeData\n"


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")
    size = float(sys.argv[2]) if len(sys.argv) > 2 else 0.0062
    steps = int(sys.argv[3]) if len(sys.argv) > 3 else 20
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, "volume_plate.msh")
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("General.NumThreads", 1)
    gmsh.option.setNumber("Mesh.RandomSeed", 1)
    gmsh.model.add("volume_plate")
    gmsh.model.occ.addBox(0, 0, 0, LENGTH, WIDTH, THICKNESS)
    gmsh.model.occ.synchronize()
    gmsh.model.addPhysicalGroup(3, [1], 1)
    gmsh.model.setPhysicalName(3, 1, "plate")
    clamp = [tag for dim, tag in gmsh.model.getEntities(2)
             if abs(gmsh.model.occ.getCenterOfMass(dim, tag)[0]) < 1e-9]
    gmsh.model.addPhysicalGroup(2, clamp, 2)
    gmsh.model.setPhysicalName(2, 2, "clamp")
    gmsh.option.setNumber("Mesh.MeshSizeMin", size)
    gmsh.option.setNumber("Mesh.MeshSizeMax", size)
    started = time.process_time()
    gmsh.model.mesh.generate(3)
    meshing_seconds = time.process_time() - started
    node_tags, coords, _ = gmsh.model.mesh.getNodes()
    points = np.asarray(coords).reshape(-1, 3)
    tetrahedra = len(gmsh.model.mesh.getElementsByType(4)[0])
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.option.setNumber("Mesh.Binary", 1)
    gmsh.write(path)
    gmsh.finalize()

    x = points[:, 0]
    shape = x * x * (6 * LENGTH**2 - 4 * LENGTH * x + x * x) / (3 * LENGTH**4)  # 1 at the free end
    with open(path, "ab") as f:
        for step in range(steps):
            displacement = np.zeros((len(node_tags), 3))
            displacement[:, 2] = -0.5 * (step + 1) / steps * shape
            displacement[:, 0] = 0.01 * (step + 1) / steps * shape * (points[:, 2] - THICKNESS / 2)
            f.write(node_data(node_tags, displacement, step))
    print(f"{path}: {tetrahedra} tetrahedra, {len(node_tags)} nodes, {steps} displacement steps, "
          f"{os.path.getsize(path) / 1e6:.1f} MB; meshing {meshing_seconds:.1f} s CPU")


if __name__ == "__main__":
    main()
