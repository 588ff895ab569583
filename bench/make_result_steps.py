#!/usr/bin/python3
"""Writes a large result file for bench/result_steps_bench.sh: a wavy square plate of 2 n^2 triangles
(MSH 4.1 binary, the layout gmsh writes) with `steps` $NodeData steps of a displacement view
(3 components, time = step), and the same mesh with no view and with one step. numpy writes the
bytes directly: gmsh's API would take minutes to pass 50 x 500K node vectors through Python lists.
Usage: make_result_steps.py OUT_PREFIX N STEPS"""
import sys

import numpy as np


def header():
    return b"$MeshFormat\n4.1 1 8\n" + np.array([1], dtype=np.int32).tobytes() + b"\n$EndMeshFormat\n"


def mesh_sections(n):
    xs = np.linspace(0.0, 1.0, n + 1)
    x, y = np.meshgrid(xs, xs, indexing="ij")
    z = 0.05 * np.sin(6 * x) * np.cos(5 * y)
    coords = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)
    count = coords.shape[0]
    tags = np.arange(1, count + 1, dtype=np.uint64)
    nodes = (b"$Nodes\n" + np.array([1, count, 1, count], dtype=np.uint64).tobytes() +
             np.array([2, 1, 0], dtype=np.int32).tobytes() + np.array([count], dtype=np.uint64).tobytes() +
             tags.tobytes() + coords.astype(np.float64).tobytes() + b"\n$EndNodes\n")
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    a = (i * (n + 1) + j + 1).ravel().astype(np.uint64)
    b, c, d = a + (n + 1), a + (n + 2), a + 1
    triangles = np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)])
    faces = triangles.shape[0]
    records = np.concatenate([np.arange(1, faces + 1, dtype=np.uint64)[:, None], triangles], axis=1)
    elements = (b"$Elements\n" + np.array([1, faces, 1, faces], dtype=np.uint64).tobytes() +
                np.array([2, 1, 2], dtype=np.int32).tobytes() + np.array([faces], dtype=np.uint64).tobytes() +
                records.tobytes() + b"\n$EndElements\n")
    return nodes + elements, coords


def node_data(coords, step, steps):
    count = coords.shape[0]
    t = float(step)
    # The plate bends the same way whatever the number of steps: the last step is always the same
    # shape (0.16 of the plate at the bench's warp factor of 20), the steps in between share it out.
    s = t / max(steps - 1, 1)
    d = np.zeros((count, 3))
    d[:, 2] = 0.008 * s * np.sin(3 * coords[:, 0] + 0.4 * s)
    record = np.zeros(count, dtype=[("tag", np.int32), ("v", np.float64, 3)])
    record["tag"] = np.arange(1, count + 1)
    record["v"] = d
    text = f'$NodeData\n1\n"displacement"\n1\n{t}\n3\n{step}\n3\n{count}\n'.encode()
    return text + record.tobytes() + b"\n$EndNodeData\n"


def main():
    prefix, n, steps = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    sections, coords = mesh_sections(n)
    with open(prefix + "_mesh.msh", "wb") as f:
        f.write(header() + sections)
    with open(prefix + "_1step.msh", "wb") as f:
        f.write(header() + sections + node_data(coords, 0, 1))
    with open(prefix + f"_{steps}steps.msh", "wb") as f:
        f.write(header() + sections)
        for k in range(steps):
            f.write(node_data(coords, k, steps))


if __name__ == "__main__":
    main()
