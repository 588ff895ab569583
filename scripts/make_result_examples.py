#!/usr/bin/python3
"""Writes the result examples in examples/results/ with the gmsh Python API (python3-gmsh): meshes made
by gmsh, with views whose values are known in closed form, written by gmsh.view.addModelData and
gmsh.view.write as a solver's post-processing would be.

beam.msh: an Euler-Bernoulli cantilever, the box [0, L] x [0, H] x [0, W] clamped at x = 0 under a
    tip load that swings as F(t) = F0 sin(2 pi t), at 9 steps t = k / 8 (time in s):
    "displacement" (3 components per node): (0, -w(x, t), 0), w = F x^2 (3 L - x) / (6 E I);
    "stress" (9 components per node, MPa): only sigma_xx = F (L - x) (y - H / 2) / I, the bending
        stress (its von Mises value is |sigma_xx|).
flow.msh: potential flow past a cylinder of radius a in a channel, the floor [-4, 4] x [-2, 2]
    (z = 0) around the cylinder's foot and the cylinder itself (height 1.2):
    "velocity" (3 components per node): u = U (1 - a^2 (x^2 - y^2) / r^4), v = -2 U a^2 x y / r^4 on
        the floor, 0 on the cylinder (so that arrows stand on the floor);
    "pressure coefficient" (1 component per node): Cp = 1 - (u^2 + v^2) / U^2 (Bernoulli).
Run: /usr/bin/python3 scripts/make_result_examples.py
"""
import math
import os
import sys

import gmsh

L, H, W = 10.0, 1.0, 1.0
E, I = 2.0e5, W * H ** 3 / 12  # MPa and mm^4, lengths in mm (steel, F0 in N: a picture, not a design)
F0 = 4.0
STEPS = 9
A, U = 0.5, 1.0


def write(path, views):
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.option.setNumber("Mesh.Binary", 1)
    gmsh.write(path)
    for v in views:
        gmsh.view.write(v, path, append=True)


def beam(root):
    gmsh.model.add("beam")
    gmsh.model.occ.addBox(0, 0, 0, L, H, W)
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.3)
    gmsh.model.mesh.generate(2)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    points = [coords[3 * i:3 * i + 3] for i in range(len(tags))]
    displacement, stress = gmsh.view.add("displacement"), gmsh.view.add("stress")
    for k in range(STEPS):
        t = k / (STEPS - 1)
        force = F0 * math.sin(2 * math.pi * t)
        w = [force * p[0] ** 2 * (3 * L - p[0]) / (6 * E * I) for p in points]
        gmsh.view.addModelData(displacement, k, "beam", "NodeData", tags, [[0.0, -d, 0.0] for d in w], time=t,
                               numComponents=3)
        sxx = [force * (L - p[0]) * (p[1] - H / 2) / I for p in points]
        gmsh.view.addModelData(stress, k, "beam", "NodeData", tags, [[s, 0, 0, 0, 0, 0, 0, 0, 0] for s in sxx],
                               time=t, numComponents=9)
    write(os.path.join(root, "beam.msh"), [displacement, stress])


def flow(root):
    gmsh.model.add("flow")
    floor = gmsh.model.occ.addRectangle(-4, -2, 0, 8, 4)
    foot = gmsh.model.occ.addDisk(0, 0, 0, A, A)
    gmsh.model.occ.cut([(2, floor)], [(2, foot)])
    gmsh.model.occ.addCylinder(0, 0, 0, 0, 0, 1.2, A)
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.16)
    gmsh.model.mesh.generate(2)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    velocity, pressure = [], []
    for i in range(len(tags)):
        x, y, z = coords[3 * i:3 * i + 3]
        r2 = max(x * x + y * y, A * A)
        u = U * (1 - A * A * (x * x - y * y) / (r2 * r2))
        v = -2 * U * A * A * x * y / (r2 * r2)
        pressure.append([1 - (u * u + v * v) / (U * U)])  # on the cylinder's wall too (r = a)
        on_floor = abs(z) < 1e-9 and x * x + y * y > A * A * (1 - 1e-6)
        velocity.append([u, v, 0.0] if on_floor else [0.0, 0.0, 0.0])  # arrows on the floor only
    views = [gmsh.view.add("velocity"), gmsh.view.add("pressure coefficient")]
    gmsh.view.addModelData(views[0], 0, "flow", "NodeData", tags, velocity, numComponents=3)
    gmsh.view.addModelData(views[1], 0, "flow", "NodeData", tags, pressure, numComponents=1)
    write(os.path.join(root, "flow.msh"), views)


def main():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples", "results")
    os.makedirs(root, exist_ok=True)
    gmsh.initialize(["gmsh", "-v", "0"])
    beam(root)
    flow(root)
    gmsh.finalize()
    for name in sorted(os.listdir(root)):
        if name.endswith(".msh"):
            print(f"{name}: {os.path.getsize(os.path.join(root, name)) / 1e6:.2f} MB", file=sys.stderr)


if __name__ == "__main__":
    main()
