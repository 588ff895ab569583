"""Makes one gmsh view fixture: opens MESH in gmsh's GUI (under a virtual display), sets the view
options given as NAME=VALUE (General.* without the prefix), and writes what gmsh itself makes of
that view: OUT.png (gmsh's export of the graphics area: the model black on white, unlit, so its
silhouette is exact) and OUT.opt (the options file gmsh saves, the changed options only).
Run by scripts/make_gmsh_view_fixtures.sh: xvfb-run /usr/bin/python3 scripts/gmsh_view_shot.py ..."""

import sys

import gmsh

mesh, out, *settings = sys.argv[1:]
# The graphics area is General.GraphicsWidth less the module menu (General.MenuWidth, 200) by
# General.GraphicsHeight: 160 x 120 pixels here, small enough to commit.
WIDTH, HEIGHT = 160, 120

gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.option.setNumber("General.GraphicsWidth", WIDTH + 200)
gmsh.option.setNumber("General.GraphicsHeight", HEIGHT)
gmsh.open(mesh)
gmsh.fltk.initialize()
# A silhouette: black faces on white, no lighting, edges, axes, text or geometry (its points are
# drawn as 4-pixel squares).
for name, value in [("General.SmallAxes", 0), ("General.Axes", 0), ("General.BackgroundGradient", 0),
                    ("Mesh.SurfaceEdges", 0), ("Mesh.VolumeEdges", 0), ("Mesh.Lines", 0), ("Mesh.Points", 0),
                    ("Mesh.SurfaceFaces", 1), ("Mesh.Light", 0), ("Mesh.ColorCarousel", 0),
                    ("Geometry.Points", 0), ("Geometry.Curves", 0), ("Geometry.Surfaces", 0)]:
    gmsh.option.setNumber(name, value)
gmsh.option.setColor("General.Background", 255, 255, 255)
gmsh.option.setColor("General.Foreground", 255, 255, 255)
gmsh.option.setColor("Mesh.Triangles", 0, 0, 0)
gmsh.option.setColor("Mesh.Quadrangles", 0, 0, 0)
for setting in settings:
    name, value = setting.split("=")
    gmsh.option.setNumber("General." + name, float(value))
for _ in range(5):
    gmsh.fltk.wait(0.05)
gmsh.graphics.draw()
gmsh.write(out + ".png")
gmsh.write(out + ".opt")
gmsh.finalize()
