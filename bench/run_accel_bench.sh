#!/usr/bin/env bash
# Makes the bench meshes that are missing (gmsh, from bench/geo/), runs the accelerator benchmarks
# and prints the tables of bench/RESULTS.md: build time and throughput, bytes per triangle, and ray throughput
# for primary, shadow and incoherent rays on 1 and 2 threads, of lancer's default accelerator (the BVH)
# beside its kd-tree and Embree, with lancer/Embree ratios from the same run, ray by ray and in packets
# of 8 (lancer's packet queries, Embree's rtcIntersect8/rtcOccluded8).
# BENCH_FILTER (a Google Benchmark regex) runs a part, e.g. BENCH_FILTER='trace/' for the rays only.
#   bench/run_accel_bench.sh [build-dir] [meshes]    e.g. bench/run_accel_bench.sh build-accel 10k,100k
# Tables show medians of 3 repetitions. Timings are wall-clock: run on an idle machine.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-build}
meshes=${2:-10k,100k,1m,4m}
mkdir -p "$here/data"
for mesh in ${meshes//,/ }; do
  out="$here/data/bracket_$mesh.msh"
  if [[ ! -f "$out" ]]; then
    echo "making $out with gmsh..." >&2
    gmsh -2 "$here/geo/bracket_$mesh.geo" -o "$out" > "$here/data/bracket_$mesh.log" 2>&1
  fi
done

results=$(mktemp -d)
echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2) x $(nproc); load before: $(cut -d' ' -f1-3 /proc/loadavg)"
# One process per mesh (only one mesh in memory), repetitions randomly interleaved so that lancer
# and Embree see the same swings in machine load.
for mesh in ${meshes//,/ }; do
  export LANCER_BENCH_MESHES=$mesh
  for program in embree_compare_bench kd_tree_bench; do
    binary="$build/bench/$program"
    if [[ ! -x "$binary" ]]; then
      echo "($program not built: skipped)" >&2
      continue
    fi
    filter=${BENCH_FILTER:-.}
    # The Embree program already runs lancer's BVH and SAH tree side by side; kd_tree_bench adds the median.
    if [[ $program == kd_tree_bench && -x "$build/bench/embree_compare_bench" ]]; then
      [[ -n ${BENCH_FILTER:-} ]] && continue  # a part of the run: the Embree program's rows only
      filter="kdtree-median"
    fi
    echo "running $program on $mesh..." >&2
    "$binary" --benchmark_filter="$filter" --benchmark_enable_random_interleaving=true \
      --benchmark_out="$results/$program-$mesh.json" --benchmark_out_format=json \
      --benchmark_report_aggregates_only=true > "$results/$program-$mesh.log" 2>&1 || { cat "$results/$program-$mesh.log"; exit 1; }
  done
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"

python3 - "$results" <<'PY'
import json, sys, glob
rows = {}
for path in glob.glob(sys.argv[1] + "/*.json"):
    for b in json.load(open(path))["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        rows[b["run_name"].split("/iterations")[0]] = b

def get(name, key):
    b = rows.get(name)
    return None if b is None else b.get(key)

def fmt(v, spec="{:.2f}"):
    return "-" if v is None else spec.format(v)

def ratio(a, b):
    return None if a is None or b is None or b == 0 else a / b

def per_cpu_second(name, amount):
    # Rays per second of the calling thread's CPU time: on a shared machine this is far steadier
    # than wall time. Only for 1-thread traces (Embree builds on its own threads even then).
    cpu = get(name, "cpu_time")  # milliseconds (the benchmarks' unit)
    return None if cpu is None or amount is None else amount / (cpu * 1e-3) * 1e-6

def size(m):
    return float(m[:-1]) * (1e3 if m[-1] == "k" else 1e6)

meshes = sorted({n.split("/")[2] for n in rows}, key=size)
default = "bvh"  # lancer's default accelerator (src/lancer/accel/accelerator.hpp, kDefaultAccel)
accels = [default, "kdtree-sah", "kdtree-median", "embree-high", "embree-medium"]
print(f"default accelerator: {default}; the kd-tree: kdtree-sah")

print("\n## Build (medians of 3; Mtris/s = triangles / wall seconds; lancer's against Embree MEDIUM and HIGH on as many threads)")
print("| mesh | triangles | accel | threads | build s | Mtris/s | bytes/tri | nodes | depth | tris/leaf | SAH cost | /Embree MEDIUM | /Embree HIGH |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for m in meshes:
    for a in accels:
        for t in (1, 2):
            n = f"build/{a}/{m}/threads:{t}"
            if n not in rows: continue
            b = rows[n]
            lancer = not a.startswith("embree")
            rm = ratio(b.get("Mtris_per_s"), get(f"build/embree-medium/{m}/threads:{t}", "Mtris_per_s")) if lancer else None
            rh = ratio(b.get("Mtris_per_s"), get(f"build/embree-high/{m}/threads:{t}", "Mtris_per_s")) if lancer else None
            print(f"| {m} | {int(b['triangles'])} | {a} | {t} | {b['real_time']/1e3:.3f} | {b['Mtris_per_s']:.2f} | {b['bytes_per_tri']:.1f} | "
                  f"{fmt(b.get('nodes'), '{:.0f}')} | {fmt(b.get('depth'), '{:.0f}')} | {fmt(b.get('tris_per_leaf'))} | {fmt(b.get('sah_cost'), '{:.1f}')} | {fmt(rm)} | {fmt(rh)} |")

traced = [default, "kdtree-sah", "kdtree-median", "embree-high"]
print("\n## Ray throughput, Mrays/s wall (medians of 3), lancer / Embree (HIGH); 1-thread rows also per CPU-second")
print(f"| mesh | rays | threads | {default} (default) | kdtree-sah | kdtree-median | embree-high | default/Embree (wall) | kd/Embree (wall) | default cpu | Embree cpu | default/Embree (cpu) | hit fraction default, kd, embree |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for m in meshes:
    for rk in ("primary", "shadow", "incoherent"):
        for t in (1, 2):
            names = {a: f"trace/{a}/{m}/{rk}/threads:{t}" for a in traced}
            v = {a: get(names[a], "Mrays_per_s") for a in traced}
            h = [get(names[a], "hit_fraction") for a in (default, "kdtree-sah", "embree-high")]
            cd = per_cpu_second(names[default], get(names[default], "rays")) if t == 1 else None
            ce = per_cpu_second(names["embree-high"], get(names["embree-high"], "rays")) if t == 1 else None
            print(f"| {m} | {rk} | {t} | {fmt(v[default])} | {fmt(v['kdtree-sah'])} | {fmt(v['kdtree-median'])} | {fmt(v['embree-high'])} | "
                  f"{fmt(ratio(v[default], v['embree-high']))} | {fmt(ratio(v['kdtree-sah'], v['embree-high']))} | {fmt(cd)} | {fmt(ce)} | {fmt(ratio(cd, ce))} | "
                  f"{fmt(h[0], '{:.4f}')}, {fmt(h[1], '{:.4f}')}, {fmt(h[2], '{:.4f}')} |")

print("\n## Packets of 8 (the same rays, 8 in a row of the set), Mrays/s wall (medians of 3)")
print("lancer packets against Embree's single rays (rtcIntersect1/rtcOccluded1) and its own packets (rtcIntersect8/rtcOccluded8, coherent context)")
print(f"| mesh | rays | threads | {default} single | {default} packets | kdtree-sah packets | embree single | embree packets | packets/single (default) | default packets / embree packets | kd packets / embree packets |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for m in meshes:
    for rk in ("primary", "shadow", "incoherent"):
        for t in (1, 2):
            ds = get(f"trace/{default}/{m}/{rk}/threads:{t}", "Mrays_per_s")
            dp = get(f"packet/{default}/{m}/{rk}/threads:{t}", "Mrays_per_s")
            kp = get(f"packet/kdtree-sah/{m}/{rk}/threads:{t}", "Mrays_per_s")
            es = get(f"trace/embree-high/{m}/{rk}/threads:{t}", "Mrays_per_s")
            ep = get(f"packet/embree-high/{m}/{rk}/threads:{t}", "Mrays_per_s")
            if dp is None and ep is None: continue
            print(f"| {m} | {rk} | {t} | {fmt(ds)} | {fmt(dp)} | {fmt(kp)} | {fmt(es)} | {fmt(ep)} | {fmt(ratio(dp, ds))} | {fmt(ratio(dp, ep))} | {fmt(ratio(kp, ep))} |")
PY
rm -rf "$results"
