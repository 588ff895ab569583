"""Python against the CLI on the same ~1M-triangle mesh (bench/python_vs_cli.sh runs it):
  1. conversion: lancer.Mesh(points, faces, groups) from numpy arrays against lancer.read_msh of
     the .msh file (MSH 4.1 binary) the arrays came from;
  2. rendering: lancer.render(mesh) (scene build, kd-tree, trace, numpy image) against `lancer
     render MESH -o x.png` (the whole process: load, build, trace, PNG).
Each figure is the best of RUNS runs; the ratios are what to read on a shared machine."""

import os
import subprocess
import sys
import tempfile
import time

import lancer

path, cli = sys.argv[1], sys.argv[2]
runs = int(os.environ.get("RUNS", "3"))
size = dict(width=800, height=600)


def best(function):
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        result = function()
        times.append(time.perf_counter() - start)
    return min(times), result


read_seconds, mesh = best(lambda: lancer.read_msh(path))
points, faces, groups = mesh.points, mesh.faces, mesh.groups
convert_seconds, _ = best(lambda: lancer.Mesh(points, faces, groups, mesh.group_names))
print(f"mesh: {len(faces)} faces, {len(points)} points")
print(f"read_msh (file)         {read_seconds:8.3f} s")
print(f"Mesh(points, faces, ..) {convert_seconds:8.3f} s   ({convert_seconds / read_seconds:.2f} of the reader)")

render_seconds, _ = best(lambda: lancer.render(mesh, **size))
with tempfile.TemporaryDirectory() as folder:
    out = os.path.join(folder, "x.png")
    command = [cli, "render", path, "-o", out, "--width", str(size["width"]), "--height", str(size["height"]), "--quiet"]
    cli_seconds, _ = best(lambda: subprocess.run(command, check=True))
    load_and_render, _ = best(lambda: lancer.render(lancer.read_msh(path), **size).save(out))
print(f"lancer.render(mesh)            {render_seconds:8.3f} s (mesh already read)")
print(f"read_msh + render + save .png  {load_and_render:8.3f} s")
print(f"lancer render MESH -o x.png    {cli_seconds:8.3f} s (whole process)")
print(f"Python file-to-PNG / CLI: {load_and_render / cli_seconds:.2f}")
