#!/usr/bin/env bash
# Regenerates the gmsh view fixtures of tests/data/gmsh_view: for each view below, the options file
# gmsh saves (NAME.opt) and gmsh's own PNG of that view (NAME.png, 160x120, the model black on white),
# made by gmsh's GUI under a virtual display. tests/python/test_gmsh_view.py checks that lancer's
# silhouette of the same view agrees with gmsh's. Needs gmsh, python3-gmsh and xvfb (xvfb-run).
set -euo pipefail
cd "$(dirname "$0")/.."
command -v xvfb-run >/dev/null || { echo "make_gmsh_view_fixtures: xvfb-run is not installed (apt-get install xvfb xauth)" >&2; exit 1; }
out=tests/data/gmsh_view
mesh=tests/data/render/bracket_coarse.msh
cp "$mesh" "$out/part.msh"
# shot NAME OPTION=VALUE...: one view of part.msh.
shot() {
  local name=$1
  shift
  xvfb-run -a -s "-screen 0 1024x768x24" /usr/bin/python3 scripts/gmsh_view_shot.py "$out/part.msh" "$out/$name" "$@"
  # The file names in the saved options are this machine's: not part of the view.
  sed -i '/^General.FileName\|^General.RecentFile\|^General.ExecutableFileName\|^General.BuildInfo\|^General.BuildOptions/d' "$out/$name.opt"
}
# Euler angles about x, y and z (General.Trackball = 0), orthographic (gmsh's default).
shot euler_xyz Trackball=0 RotationX=30 RotationY=20 RotationZ=10
shot euler_x Trackball=0 RotationX=-60
# Trackball quaternions (x, y, z, w) for turns about x (40 degrees), y (50), z (30).
shot trackball_x TrackballQuaternion0=0.3420201433 TrackballQuaternion3=0.9396926208
shot trackball_y TrackballQuaternion1=0.4226182617 TrackballQuaternion3=0.9063077870
shot trackball_z TrackballQuaternion2=0.2588190451 TrackballQuaternion3=0.9659258263
# Translated and zoomed (gmsh's mouse pan and zoom).
shot translated_scaled TrackballQuaternion0=0.2 TrackballQuaternion1=0.3 TrackballQuaternion3=0.9327379053 \
  TranslationX=0.4 TranslationY=-0.3 ScaleX=1.5 ScaleY=1.5 ScaleZ=1.5
# gmsh's perspective (General.Orthographic = 0), with a turn and with a zoom.
shot perspective TrackballQuaternion0=0.3420201433 TrackballQuaternion3=0.9396926208 Orthographic=0
shot perspective_euler_scaled Trackball=0 RotationX=20 RotationY=-35 ScaleX=1.3 ScaleY=1.3 ScaleZ=1.3 Orthographic=0
