#!/usr/bin/env bash
# gmsh_print_shot.sh MESH OUT WIDTH HEIGHT [NAME=VALUE...]: one gmsh print fixture. Opens MESH in
# gmsh's GUI with a 160x120 graphics area (under a virtual display), sets the view options given as
# NAME=VALUE (General.* without the prefix), and writes what gmsh itself makes of that view:
# OUT.png, gmsh's Print at Print.Width x Print.Height = WIDTH x HEIGHT (the model black on white,
# unlit, so its silhouette is exact), and OUT.opt, the options file gmsh saves. A .geo script, not
# the Python API: gmsh.write() of a print size waits forever for its print window under xvfb-run.
# Run by scripts/make_gmsh_print_fixtures.sh; needs gmsh and xvfb (xvfb-run).
set -euo pipefail
mesh=$1 out=$2 width=$3 height=$4
shift 4
script=$(mktemp --suffix=.geo)
trap 'rm -f "$script"' EXIT
{
  echo "General.Terminal = 0;"
  # The graphics area is General.GraphicsWidth less the module menu (General.MenuWidth, 200).
  echo "General.GraphicsWidth = 360; General.GraphicsHeight = 120;"
  echo "Merge \"$(realpath "$mesh")\";"
  # A silhouette: black faces on white, no lighting, edges, axes or text.
  for option in General.SmallAxes=0 General.Axes=0 General.BackgroundGradient=0 Mesh.SurfaceEdges=0 \
    Mesh.VolumeEdges=0 Mesh.Lines=0 Mesh.Points=0 Mesh.SurfaceFaces=1 Mesh.Light=0 Mesh.ColorCarousel=0 \
    Geometry.Points=0 Geometry.Curves=0 Geometry.Surfaces=0; do
    echo "${option%%=*} = ${option#*=};"
  done
  echo "General.Color.Background = {255, 255, 255}; General.Color.Foreground = {255, 255, 255};"
  echo "Mesh.Color.Triangles = {0, 0, 0}; Mesh.Color.Quadrangles = {0, 0, 0};"
  for setting in "$@"; do echo "General.${setting%%=*} = ${setting#*=};"; done
  echo "Print.Width = $width; Print.Height = $height;"
  echo "Draw;"
  echo "Print \"$(realpath -m "$out").png\";"
  echo "Save \"$(realpath -m "$out").opt\";"
  echo "Exit;"
} >"$script"
timeout 120 xvfb-run -a -s "-screen 0 1024x768x24" gmsh "$script"
