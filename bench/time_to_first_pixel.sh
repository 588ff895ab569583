#!/usr/bin/env bash
# Where a user waits before the first ray, on the bench brackets (10K to 4M triangles, converted to
# MSH 4.1 binary as gmsh users save big meshes): per mesh, a minimal reader's parse, lancer's read
# and scene preparation, the kd-tree build against Embree 3's MEDIUM and HIGH builds on 1 and 2
# threads (bench/first_pixel_embree_bench.cpp; wall and CPU seconds: on a shared machine the CPU
# seconds are the steadier), the tree's trace speed, and the peak memory of `lancer render`. Ratios come from one run (stages interleaved); end to end
# against POV-Ray is bench/povray_compare.sh.
#   bench/time_to_first_pixel.sh [build-dir] [meshes] [repetitions]   e.g. bench/time_to_first_pixel.sh build 1m,4m 3
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-build}" && pwd)
meshes=${2:-10k,100k,1m,4m}
repetitions=${3:-3}
bench="$build/bench/first_pixel_embree_bench"
if [[ ! -x $bench ]]; then
  echo "missing $bench (Embree not installed, or the project not built): skipping" >&2
  exit 0
fi
command -v gmsh > /dev/null || { echo "gmsh is needed to make the bench meshes" >&2; exit 1; }
mkdir -p "$here/data"
results=$(mktemp -d)
trap 'rm -rf "$results"' EXIT
echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2) x $(nproc); load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for mesh in ${meshes//,/ }; do
  ascii="$here/data/bracket_$mesh.msh"
  binary="$here/data/bracket_${mesh}_bin.msh"
  if [[ ! -f $ascii ]]; then
    echo "making $ascii with gmsh..." >&2
    gmsh -2 "$here/geo/bracket_$mesh.geo" -o "$ascii" > "$here/data/bracket_$mesh.log" 2>&1
  fi
  [[ -f $binary ]] || gmsh "$ascii" -save -bin -format msh41 -o "$binary" > /dev/null 2>&1
  echo "stages of $mesh..." >&2
  "$bench" "$binary" "$repetitions" > "$results/$mesh.jsonl"
  # Peak memory of the whole render as a user runs it (800x600, 4 samples, 2 threads).
  /usr/bin/time -f '%M' -o "$results/$mesh.rss" "$build/lancer" render "$binary" -o "$results/$mesh.png" \
    --width 800 --height 600 --samples 4 --threads 2 2> "$results/$mesh-render.log" || cat "$results/$mesh-render.log"
  tail -1 "$results/$mesh.rss" > "$results/$mesh.peak_kb"
  grep -h 'load .* s, build' "$results/$mesh-render.log" | tail -1 > "$results/$mesh.summary" || true
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"

python3 - "$results" "$meshes" <<'PY'
import json, sys
folder, meshes = sys.argv[1], sys.argv[2].split(",")
rows = {}
for m in meshes:
    for line in open(f"{folder}/{m}.jsonl"):
        r = json.loads(line)
        rows[(m, r["stage"], r["threads"])] = r
tris = {m: next(r["triangles"] for (mm, _, _), r in rows.items() if mm == m) for m in meshes}

def s(m, stage, threads):
    r = rows.get((m, stage, threads))
    return None if r is None else r["seconds"]

def f(v, spec="{:.3f}"):
    return "-" if v is None else spec.format(v)

def ratio(a, b):
    return None if a is None or b is None or b == 0 else a / b

print("\n## Load (seconds, medians; scene = orient (shells, orientation, nesting) + normals + the rest; load = read + scene on 2 threads)")
print("| mesh | triangles | minimal parse | lancer read | scene 1T (orient + normals + rest) | scene 2T (orient + normals + rest) | lancer load | load / parse |")
print("|---|---|---|---|---|---|---|---|")
def scene_cell(m, t):
    r = rows.get((m, "lancer scene", t))
    if r is None:
        return "-"
    return f"{r['seconds']:.3f} ({r.get('orient', 0):.3f} + {r.get('normals', 0):.3f} + {r.get('scene', 0):.3f})"
for m in meshes:
    parse, read, scene = s(m, "minimal parse", 1), s(m, "lancer read", 1), s(m, "lancer scene", 2)
    load = read + scene
    print(f"| {m} | {tris[m]} | {f(parse)} | {f(read)} | {scene_cell(m, 1)} | {scene_cell(m, 2)} | {f(load)} | {f(ratio(load, parse), '{:.2f}')} |")
if "1m" in meshes and "4m" in meshes:
    l1 = s("1m", "lancer read", 1) + s("1m", "lancer scene", 2)
    l4 = s("4m", "lancer read", 1) + s("4m", "lancer scene", 2)
    print(f"\nload 4M / 1M: {l4 / l1:.2f} (triangles {tris['4m'] / tris['1m']:.2f}x)")

print("\n## Build (seconds, medians; Embree / lancer > 1: lancer builds faster)")
print("| mesh | threads | kdtree-sah wall | cpu | Embree MEDIUM wall | cpu | Embree HIGH wall | cpu | vs MEDIUM wall / cpu | vs HIGH wall / cpu | SAH cost | bytes/tri |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
def c(m, stage, t):
    r = rows.get((m, stage, t))
    return None if r is None else r["cpu_seconds"]
for m in meshes:
    for t in (1, 2):
        d, med, high = s(m, "kdtree-sah build", t), s(m, "embree-medium build", t), s(m, "embree-high build", t)
        dc, medc, highc = c(m, "kdtree-sah build", t), c(m, "embree-medium build", t), c(m, "embree-high build", t)
        rd = rows[(m, "kdtree-sah build", t)]
        print(f"| {m} | {t} | {f(d)} | {f(dc)} | {f(med)} | {f(medc)} | {f(high)} | {f(highc)} | "
              f"{f(ratio(med, d), '{:.2f}')} / {f(ratio(medc, dc), '{:.2f}')} | "
              f"{f(ratio(high, d), '{:.2f}')} / {f(ratio(highc, dc), '{:.2f}')} | "
              f"{rd['sah_cost']:.1f} | {rd['bytes'] / tris[m]:.0f} |")
        for other in ("kdtree-sah-exact", "kdtree-sah-variant"):
          v = rows.get((m, f"{other} build", t))
          if v:
            print(f"| {m} | {t} | {other[11:]} {v['seconds']:.3f} | {v['cpu_seconds']:.3f} | | | | | "
                  f"{f(ratio(med, v['seconds']), '{:.2f}')} / {f(ratio(medc, v['cpu_seconds']), '{:.2f}')} | "
                  f"{f(ratio(high, v['seconds']), '{:.2f}')} / {f(ratio(highc, v['cpu_seconds']), '{:.2f}')} | "
                  f"{v['sah_cost']:.1f} | {v['bytes'] / tris[m]:.0f} |")

print("\n## Trace on the tree (1 thread, Mrays per CPU second, medians)")
print("| mesh | tree | primary | shadow | incoherent |")
print("|---|---|---|---|---|")
for m in meshes:
    for tree in ("kdtree-sah", "kdtree-sah-exact", "kdtree-sah-variant"):
        cells = [rows.get((m, f"{tree} trace {k}", 1)) for k in ("primary", "shadow", "incoherent")]
        if all(cells):
            print(f"| {m} | {tree} | " + " | ".join(f"{r['mrays_per_cpu_s']:.2f}" for r in cells) + " |")

print("\n## `lancer render` (800x600, 4 samples, 2 threads): peak memory")
print("| mesh | triangles | peak RSS MB | bytes/triangle | summary |")
print("|---|---|---|---|---|")
for m in meshes:
    kb = int(open(f"{folder}/{m}.peak_kb").read().split()[-1])
    summary = open(f"{folder}/{m}.summary").read().strip()
    summary = summary[summary.find("load"):] if "load" in summary else summary
    print(f"| {m} | {tris[m]} | {kb / 1024:.0f} | {kb * 1024 / tris[m]:.0f} | {summary} |")
PY
