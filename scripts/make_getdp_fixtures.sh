#!/usr/bin/env bash
# Regenerates tests/data/getdp/ with the real GetDP (Debian's getdp 3.2) on its own magnet demo
# (/usr/share/doc/getdp/examples/demos/magnet.pro, a 2D magnetostatic problem), meshed coarser by
# gmsh: magnet_v2_az.pos and magnet_v2_b.pos are what `getdp ... -pos a -v2` writes, MSH 2.2 files
# whose data are $ElementNodeData (the potential az, the flux density b, a vector that jumps between
# elements).
set -euo pipefail
cd "$(dirname "$0")/.."
for tool in gmsh getdp; do
  command -v "$tool" >/dev/null || { echo "make_getdp_fixtures.sh: $tool is not installed (apt-get install $tool)" >&2; exit 1; }
done
out=$(realpath tests/data/getdp)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
examples=/usr/share/doc/getdp/examples
mkdir -p "$work/demos"
cp "$examples"/demos/magnet.geo "$examples"/demos/magnet.pro "$examples"/demos/magnet_data.pro "$work/demos/"
cp -r "$examples/templates" "$work/templates"  # magnet.pro includes ../templates/*.pro
gunzip -f "$work"/templates/*.gz 2>/dev/null || true
(
  cd "$work/demos"
  gmsh magnet.geo -2 -clscale 2.5 -format msh22 -o magnet.msh -v 0
  getdp magnet.pro -msh magnet.msh -solve Magnetostatics_a -pos a -v2 -v 0
)
cp "$work/demos/az.pos" "$out/magnet_v2_az.pos"
cp "$work/demos/b_a.pos" "$out/magnet_v2_b.pos"
