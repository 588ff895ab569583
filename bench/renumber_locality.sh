#!/usr/bin/env bash
# What renumbering a mesh in Morton order (src/lancer/mesh/morton_renumbering.hpp) buys: an older
# binary (without it) and this one render the same gmsh-made brackets alternately, 800x600, 4 spp,
# on 1 and 2 threads, and each run's `--timings` stages (renumber, orient, normals, accel build),
# summary trace time and peak RSS (the table's "peak", MiB) are kept; medians per binary, mesh and
# thread count, and how much the two pictures differ (faces that tie at shared edges and the last
# bits of smooth normals may).
#   bench/renumber_locality.sh OLD_BINARY [build-dir] [mesh files] [rounds]
#   e.g. bench/renumber_locality.sh /tmp/old/lancer build /tmp/bracket_1m_bin.msh,/tmp/bracket_4m_bin.msh 5
set -euo pipefail
old=${1:?old binary}
build=${2:-build}
meshes=${3:?comma-separated mesh files (bench/geo/bracket_*.geo, meshed by gmsh)}
rounds=${4:-5}
new="$build/lancer"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for mesh in ${meshes//,/ }; do
  for threads in 1 2; do
    for ((i = 0; i < rounds; ++i)); do
      for which in old new; do
        binary=$old
        [[ $which == new ]] && binary=$new
        /usr/bin/time -f 'peak %M KB' "$binary" render "$mesh" -o "$work/$which.png" --width 800 --height 600 --samples 4 \
          --threads "$threads" --timings > /dev/null 2> "$work/log"
        stages=$(grep -o 'timings:.*' "$work/log")
        trace=$(grep -o 'trace [0-9.]* s' "$work/log" | tail -1)
        peak=$(grep -o 'peak [0-9]* KB' "$work/log" | grep -o '[0-9]*')
        echo "$(basename "$mesh") $threads $which $stages, $trace, peak $((peak / 1024)) s" >> "$work/runs"
      done
    done
    python3 - "$work/old.png" "$work/new.png" "$(basename "$mesh")" "$threads" <<'PY'
import sys, zlib, struct
def pixels(path):  # 8-bit RGB(A) PNG without interlace, as lancer writes it
    data = open(path, "rb").read()
    pos, idat, width, height, channels = 8, b"", 0, 0, 3
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            channels = {2: 3, 6: 4}[colour]
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows, prev = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b, c = prev[x], prev[x - channels] if x >= channels else 0
            p = a + b - c
            pred = [0, a, b, (a + b) // 2,
                    a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else (b if abs(p - b) <= abs(p - c) else c)][kind]
            line[x] = (line[x] + pred) & 255
        rows.append(line)
        prev = line
    return width, channels, rows
w, ch, a = pixels(sys.argv[1])
_, _, b = pixels(sys.argv[2])
differ = sum(1 for ra, rb in zip(a, b) for x in range(w) if ra[x * ch:x * ch + ch] != rb[x * ch:x * ch + ch])
big = sum(1 for ra, rb in zip(a, b) for x in range(w) if max(abs(p - q) for p, q in zip(ra[x * ch:x * ch + ch], rb[x * ch:x * ch + ch])) > 8)
print(f"{sys.argv[3]} {sys.argv[4]} threads: {differ} of {w * len(a)} pixels differ, {big} by more than 8/255")
PY
  done
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "$work/runs" <<'PY'
import re, statistics, sys
runs = {}
for line in open(sys.argv[1]):
    mesh, threads, which, rest = line.split(" ", 3)
    for name, value in re.findall(r"([a-z ]+) ([0-9.]+) s", rest.replace("timings:", ",")):
        runs.setdefault((mesh, threads, which, name.strip(" ,")), []).append(float(value))
keys = sorted({(m, t) for m, t, _, _ in runs})
stages = ["read", "renumber", "orient", "normals", "scene", "accel build", "trace", "peak"]
print("| mesh | threads | binary | " + " | ".join(stages) + " | orient + normals (+ renumber) |")
print("|---|---|---|" + "---|" * (len(stages) + 1))
for mesh, threads in keys:
    for which in ["old", "new"]:
        med = {s: statistics.median(runs[(mesh, threads, which, s)]) for s in stages if (mesh, threads, which, s) in runs}
        cells = [f"{med[s]:.3f}" if s in med else "-" for s in stages]
        total = med.get("orient", 0) + med.get("normals", 0) + med.get("renumber", 0)
        print(f"| {mesh} | {threads} | {which} | " + " | ".join(cells) + f" | {total:.3f} |")
PY
