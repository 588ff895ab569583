#!/usr/bin/env bash
# Time to first pixel of `lancer render` on the bench brackets, builds side by side: the page
# faults of the whole run (/usr/bin/time), the wall and CPU time, the load, the build's unhidden part
# and each preparation stage (--timings), peak RSS, medians of interleaved runs. 800x600, 4 samples,
# 2 threads.
#   bench/load_pipeline.sh OLD_LANCER NEW_LANCER [meshes] [repetitions]
#   bench/load_pipeline.sh NAME=LANCER,NAME=LANCER,... [meshes] [repetitions]
#   e.g. bench/load_pipeline.sh /tmp/base/build/lancer build/lancer 1m,4m 5
# The meshes are bench/data/bracket_<mesh>_bin.msh (bench/python_vs_cli.sh says how gmsh makes them).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
if [[ $1 == *=* ]]; then
  builds=$1
  shift
else
  builds="old=$1,new=$2"
  shift 2
fi
meshes=${1:-1m,4m}
repetitions=${2:-5}
names=()
declare -A binaries
for pair in ${builds//,/ }; do
  names+=("${pair%%=*}")
  binaries[${pair%%=*}]=${pair#*=}
done
results=$(mktemp -d)
trap 'rm -rf "$results"' EXIT
echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2) x $(nproc); load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for mesh in ${meshes//,/ }; do
  input="$here/data/bracket_${mesh}_bin.msh"
  [[ -f $input ]] || { echo "missing $input (see bench/python_vs_cli.sh for the gmsh command)" >&2; exit 1; }
  for ((r = 0; r < repetitions; ++r)); do
    for which in "${names[@]}"; do
      binary=${binaries[$which]}
      /usr/bin/time -f 'time %e %U %S %R %M' -o "$results/time" "$binary" render "$input" \
        -o "$results/out.ppm" --width 800 --height 600 --samples 4 --threads 2 --timings 2> "$results/log"
      { grep -h 'load .* s, build' "$results/log"; grep -h '^timings:' "$results/log"; tail -1 "$results/time"; } |
        tr '\n' ' ' >> "$results/$mesh-$which"
      echo >> "$results/$mesh-$which"
    done
  done
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "$results" "$meshes" "${names[@]}" <<'PY'
import re, statistics, sys
folder, meshes, names = sys.argv[1], sys.argv[2].split(","), sys.argv[3:]
def parse(line):
    row = {}
    m = re.search(r"load ([0-9.]+) s, build ([0-9.]+) s, trace ([0-9.]+) s", line)
    row["load"], row["build"], row["trace"] = map(float, m.groups())
    row["first pixel"] = row["load"] + row["build"]
    for name, seconds in re.findall(r"([a-z ]+) ([0-9.]+) s", line.split("timings:")[1]):
        row[name.strip()] = float(seconds)
    wall, user, system, faults, rss = line.split("time ")[1].split()[:5]
    row["wall"], row["cpu"], row["faults"], row["peak MB"] = float(wall), float(user) + float(system), int(faults), int(rss) / 1024
    return row
columns = ["faults", "wall", "cpu", "first pixel", "load", "build", "trace", "read", "setup", "renumber", "orient", "normals", "scene", "accel build", "peak MB"]
print("| mesh | build | " + " | ".join(columns) + " | orient + normals |")
print("|---|---|" + "---|" * (len(columns) + 1))
medians = {}
for mesh in meshes:
    for which in names:
        rows = [parse(line) for line in open(f"{folder}/{mesh}-{which}") if line.strip()]
        # A stage a build does not time (older builds have no "setup") counts 0.
        med = {c: statistics.median(r.get(c, 0.0) for r in rows) for c in columns}
        med["orient + normals"] = statistics.median(r["orient"] + r["normals"] for r in rows)
        medians[(mesh, which)] = med
        cells = [f"{med[c]:.0f}" if c in ("faults", "peak MB") else f"{med[c]:.3f}" for c in columns]
        print(f"| {mesh} | {which} | " + " | ".join(cells) + f" | {med['orient + normals']:.3f} |")
if "1m" in meshes and "4m" in meshes:
    for which in names:
        a, b = medians[("1m", which)], medians[("4m", which)]
        print(f"\n{which}: orient + normals 4M / 1M = {b['orient + normals'] / a['orient + normals']:.2f}x "
              f"(orient {b['orient'] / a['orient']:.2f}x, normals {b['normals'] / a['normals']:.2f}x)")
PY
