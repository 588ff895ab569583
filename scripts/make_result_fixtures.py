#!/usr/bin/python3
"""Regenerates the result fixtures in tests/data/results/ with the gmsh Python API (python3-gmsh).

A cantilever: the box [0, L] x [0, H] x [0, H], clamped at x = 0, meshed on its surface, with views
known in closed form at steps k = 0..3, time t_k = 0.5 k:
  "displacement" (3 components per node): (0, -w(x, t), 0), w = t x^2 (3 L - x) / (2 L^3), the
      Euler-Bernoulli deflection under a tip load growing with t (the tip moves down by t);
  "stress" (9 components per node): only sigma_xx = t (L - x) (y - H/2), the bending stress (its
      von Mises value is |sigma_xx|);
  "temperature" (1 component per element): 10 t + the element's tag mod 3.
cantilever.msh holds all steps of all views (MSH 4.1, binary); cantilever.msh.opt, discrete.opt,
hidden.opt and colormap.opt are gmsh's options files for views set up in its GUI (VIEW_OPTIONS); steps/step_1.msh, step_2.msh,
step_10.msh hold one step each of "displacement" (t = 1, 2 and 10 times 0.1), for patterns and
natural sort.
Run: /usr/bin/python3 scripts/make_result_fixtures.py
"""
import os
import sys

import gmsh

L, H = 10.0, 1.0
STEPS = [0, 1, 2, 3]


def deflection(x, t):
    return t * x * x * (3 * L - x) / (2 * L ** 3)


def make_mesh():
    gmsh.model.add("cantilever")
    gmsh.model.occ.addBox(0, 0, 0, L, H, H)
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.5)
    gmsh.option.setNumber("Mesh.MeshSizeMin", 0.5)
    gmsh.model.mesh.generate(2)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    return list(tags), [coords[3 * i:3 * i + 3] for i in range(len(tags))]


def add_views(tags, points, steps, time_of, names):
    views = []
    if "displacement" in names:
        v = gmsh.view.add("displacement")
        for k in steps:
            t = time_of(k)
            data = [[0.0, -deflection(p[0], t), 0.0] for p in points]
            gmsh.view.addModelData(v, k, "cantilever", "NodeData", tags, data, time=t, numComponents=3)
        views.append(v)
    if "stress" in names:
        v = gmsh.view.add("stress")
        for k in steps:
            t = time_of(k)
            data = [[t * (L - p[0]) * (p[1] - H / 2), 0, 0, 0, 0, 0, 0, 0, 0] for p in points]
            gmsh.view.addModelData(v, k, "cantilever", "NodeData", tags, data, time=t, numComponents=9)
        views.append(v)
    if "temperature" in names:
        v = gmsh.view.add("temperature")
        element_types, element_tags, _ = gmsh.model.mesh.getElements(2)
        faces = [int(e) for e in element_tags[0]]
        for k in steps:
            t = time_of(k)
            gmsh.view.addModelData(v, k, "cantilever", "ElementData", faces, [[10 * t + e % 3] for e in faces],
                                   time=t, numComponents=1)
        views.append(v)
    return views


def write(path, views):
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.option.setNumber("Mesh.Binary", 1)
    gmsh.option.setNumber("PostProcessing.SaveMesh", 0)
    gmsh.write(path)
    for v in views:
        gmsh.view.write(v, path, append=True)


# The options files: cantilever.msh.opt (the displacement drawn as the deformed shape, x3, the
# stress at step 2 on a custom range with iso-values, the temperature hidden), discrete.opt (the
# stress in 5 filled bands without its scale), hidden.opt (every view hidden) and colormap.opt (the
# stress in gmsh's colour map 7, "hot", swapped).
VIEW_OPTIONS = {
    "cantilever.msh.opt": [("View[0].VectorType", 5), ("View[0].DisplacementFactor", 3), ("View[1].RangeType", 2),
                           ("View[1].CustomMin", 1), ("View[1].CustomMax", 4), ("View[1].TimeStep", 2),
                           ("View[1].IntervalsType", 1), ("View[1].NbIso", 8), ("View[2].Visible", 0),
                           ("General.Trackball", 0), ("General.RotationX", 10)],
    "discrete.opt": [("View[0].Visible", 0), ("View[1].IntervalsType", 3), ("View[1].NbIso", 5),
                     ("View[1].ShowScale", 0), ("View[2].Visible", 0)],
    "hidden.opt": [("View[0].Visible", 0), ("View[1].Visible", 0), ("View[2].Visible", 0)],
    "colormap.opt": [("View[0].Visible", 0), ("View[1].ColormapNumber", 7), ("View[1].ColormapSwap", 1),
                     ("View[2].Visible", 0)],
}


def write_view_options(root):
    """Each options file as gmsh's "Save Model Options" writes it for views set up in the GUI. gmsh
    writes each view's FileName as an absolute path: those lines are dropped (lancer does not read
    them; the file stays the same on every machine)."""
    for name, options in VIEW_OPTIONS.items():
        write_options_file(root, name, options)


def write_options_file(root, name, options):
    gmsh.initialize(["gmsh", "-v", "0"])
    gmsh.open(os.path.join(root, "cantilever.msh"))
    for option, value in options:
        gmsh.option.setNumber(option, value)
    path = os.path.join(root, name)
    gmsh.write(path)
    gmsh.finalize()
    with open(path) as f:
        lines = [line for line in f if ".FileName = " not in line]
    with open(path, "w") as f:
        f.writelines(lines)


def main():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data", "results")
    os.makedirs(os.path.join(root, "steps"), exist_ok=True)
    gmsh.initialize(["gmsh", "-v", "0"])
    tags, points = make_mesh()
    views = add_views(tags, points, STEPS, lambda k: 0.5 * k, {"displacement", "stress", "temperature"})
    write(os.path.join(root, "cantilever.msh"), views)
    for v in views:
        gmsh.view.remove(v)
    for n in (1, 2, 10):
        views = add_views(tags, points, [0], lambda k, n=n: 0.1 * n, {"displacement"})
        write(os.path.join(root, "steps", f"step_{n}.msh"), views)
        for v in views:
            gmsh.view.remove(v)
    gmsh.finalize()
    write_view_options(root)
    print("result fixtures:", ", ".join(sorted(os.listdir(root))), file=sys.stderr)


if __name__ == "__main__":
    main()
