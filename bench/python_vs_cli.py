"""Python against the CLI on the same ~1M-triangle mesh (bench/python_vs_cli.sh runs it):
  1. conversion: lancer.Mesh(points, faces, groups) from numpy arrays against lancer.read_msh of
     the .msh files the arrays came from (MSH 4.1 binary, and ASCII when given);
  2. rendering: read_msh + lancer.render + Image.save against `lancer render MESH -o x.png` (the
     whole process: load, kd-tree build, trace, PNG), runs interleaved, and the trace alone.
Each figure is the best of RUNS runs; on a shared machine read the ratios."""

import os
import re
import subprocess
import sys
import tempfile
import time

import lancer

binary, cli = sys.argv[1], sys.argv[2]
ascii_path = sys.argv[3] if len(sys.argv) > 3 else None
runs = int(os.environ.get("RUNS", "5"))
width, height = 800, 600


def best(function):
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


mesh = lancer.read_msh(binary)
points, faces, groups, names = mesh.points, mesh.faces, mesh.groups, mesh.group_names
print(f"mesh: {len(faces)} faces, {len(points)} points")
for threads in (1, 0):  # one thread, then every core (the assembly after the parse is parallel)
    label = "1 thread" if threads == 1 else "all cores"
    convert = best(lambda: lancer.Mesh(points, faces, groups=groups, group_names=names, threads=threads))
    read_binary = best(lambda: lancer.read_msh(binary, threads=threads))
    print(f"[{label}] Mesh(points, faces, groups) {convert:7.3f} s")
    print(f"[{label}] read_msh, MSH 4.1 binary    {read_binary:7.3f} s   arrays / reader: {convert / read_binary:.2f}")
    if ascii_path:
        read_ascii = best(lambda: lancer.read_msh(ascii_path, threads=threads))
        print(f"[{label}] read_msh, MSH 4.1 ASCII     {read_ascii:7.3f} s   arrays / reader: {convert / read_ascii:.2f}")

with tempfile.TemporaryDirectory() as folder:
    out = os.path.join(folder, "x.png")
    command = [cli, "render", binary, "-o", out, "--width", str(width), "--height", str(height)]
    python_total, cli_total, python_trace, cli_trace = [], [], [], []
    for _ in range(runs):  # interleaved, so that both see the same machine load
        start = time.perf_counter()
        stderr = subprocess.run(command, check=True, capture_output=True, text=True).stderr
        cli_total.append(time.perf_counter() - start)
        cli_trace.append(float(re.search(r"trace ([0-9.]+) s", stderr).group(1)))
        start = time.perf_counter()
        image = lancer.render(lancer.read_msh(binary), width=width, height=height)
        image.save(out)
        python_total.append(time.perf_counter() - start)
        python_trace.append(image.stats["seconds"])
print(f"file to PNG: Python {min(python_total):6.3f} s, CLI {min(cli_total):6.3f} s (whole process)   "
      f"Python / CLI: {min(python_total) / min(cli_total):.2f}")
print(f"trace only:  Python {min(python_trace):6.3f} s, CLI {min(cli_trace):6.3f} s   "
      f"Python / CLI: {min(python_trace) / min(cli_trace):.2f}")
