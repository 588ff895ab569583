"""A turntable of a gmsh mesh, as `lancer animate part.msh -o turntable.gif` makes it, from Python;
and the same frames as numpy arrays, for a notebook or a video writer.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/turntable.py [MESH.msh] [OUT.gif]
"""

import sys

import numpy as np

import lancer

path = sys.argv[1] if len(sys.argv) > 1 else "examples/meshes/bracket.msh"
out = sys.argv[2] if len(sys.argv) > 2 else "turntable.gif"

mesh = lancer.read_msh(path)
lancer.animate(mesh, out, frames=24, fps=10, width=240, height=180, samples=4)
print(f"{path}: 24 frames at 10 fps -> {out}")

# The frames themselves: turn a camera about the model's up axis and render each view.
scene = lancer.Scene.quick_look(mesh)
centre = np.mean(mesh.points, axis=0)
radius = np.ptp(mesh.points, axis=0).max() * 1.6
frames = []
for k in range(4):
    angle = 2 * np.pi * k / 4
    scene.camera = lancer.Camera(position=tuple(centre + radius * np.array([np.sin(angle), 0.6, np.cos(angle)])),
                                 look_at=tuple(centre), up=(0, 1, 0), fov=35)
    frames.append(lancer.render(scene, width=160, height=120))
print(f"4 views as arrays: {np.stack(frames).shape}")
