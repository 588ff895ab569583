#!/usr/bin/env bash
# Regenerates the gmsh print fixtures of tests/data/gmsh_print: views set up in a 160x120 graphics
# area and exported by gmsh's own Print at other sizes and aspects (Print.Width x Print.Height), of a
# wide and a tall model (made here from their .geo files) and of the bracket, orthographic and
# perspective. For each: NAME.opt (the options file gmsh saves) and NAME.png (gmsh's print, the model
# black on white). tests/python/test_gmsh_print.py checks lancer's silhouette at the print's size
# against gmsh's (intersection over union). Needs gmsh and xvfb (xvfb-run).
set -euo pipefail
cd "$(dirname "$0")/.."
command -v xvfb-run >/dev/null || { echo "make_gmsh_print_fixtures: xvfb-run is not installed (apt-get install xvfb xauth)" >&2; exit 1; }
source scripts/gmsh_quiet.sh
out=tests/data/gmsh_print
for model in wide tall; do
  quiet gmsh "$out/$model.geo" -2 -format msh41 -bin -o "$out/$model.msh"
  rm -f "$out/$model.geo_unrolled"
done
# shot NAME MODEL WIDTH HEIGHT OPTION=VALUE...: MODEL's view printed at WIDTH x HEIGHT; MODEL is wide,
# tall or part (tests/data/gmsh_view/part.msh, the bracket).
shot() {
  local name=$1 model=$2 width=$3 height=$4
  shift 4
  local mesh="$out/$model.msh"
  [ "$model" = part ] && mesh=tests/data/gmsh_view/part.msh
  scripts/gmsh_print_shot.sh "$mesh" "$out/$name" "$width" "$height" "$@"
  # The file names in the saved options are this machine's: not part of the view.
  sed -i '/^General.FileName\|^General.RecentFile\|^General.ExecutableFileName\|^General.BuildInfo\|^General.BuildOptions/d' "$out/$name.opt"
}
# A wide model printed wider than the window, and taller (then its width fits the image).
shot wide_ortho_240x100 wide 240 100 Trackball=0 RotationX=20 RotationY=-30
shot wide_ortho_100x180 wide 100 180 Trackball=0 RotationX=-25 RotationY=15 RotationZ=10
shot wide_perspective_120x200 wide 120 200 Trackball=0 RotationX=30 RotationY=25 Orthographic=0
# A tall model printed wide and tall.
shot tall_ortho_240x120 tall 240 120 Trackball=0 RotationX=15 RotationY=30
shot tall_ortho_100x200 tall 100 200 TrackballQuaternion0=0.2588190451 TrackballQuaternion3=0.9659258263
shot tall_perspective_260x120 tall 260 120 Trackball=0 RotationX=-20 RotationY=40 Orthographic=0
# The bracket: the window's aspect at twice its size, and a square print, panned and zoomed.
shot part_ortho_320x240 part 320 240 Trackball=0 RotationX=30 RotationY=20 RotationZ=10
shot part_perspective_200x200 part 200 200 Trackball=0 RotationX=20 RotationY=-35 \
  ScaleX=1.3 ScaleY=1.3 ScaleZ=1.3 TranslationX=0.2 Orthographic=0
