#!/usr/bin/env bash
# The BVH build against Embree 3's MEDIUM build, each the first build of a fresh process (what a user
# waits for: fresh pages, threads started), 1 and 2 threads, and the same rows' later builds in that
# process (warm). Optionally a second embree_compare_bench binary (an older lancer) runs interleaved
# with the first, so before/after and Embree share the machine's swings in one run.
#   bench/bvh_build_fresh.sh [mesh] [repetitions] [binary] [other-binary]
#   e.g. bench/bvh_build_fresh.sh 1m 5 build/bench/embree_compare_bench /tmp/old_embree_compare_bench
# Prints medians: first build (fresh) and warm build wall seconds, lancer's SAH cost, the structure's
# bytes a triangle, ratios to MEDIUM.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
mesh=${1:-1m}
repetitions=${2:-5}
binaries=("${3:-build/bench/embree_compare_bench}")
[[ -n ${4:-} ]] && binaries+=("$4")
for b in "${binaries[@]}"; do [[ -x $b ]] || { echo "missing $b" >&2; exit 1; }; done
[[ -f $here/data/bracket_$mesh.msh ]] || { echo "missing $here/data/bracket_$mesh.msh (bench/run_accel_bench.sh makes it)" >&2; exit 1; }
results=$(mktemp -d)
trap 'rm -rf "$results"' EXIT
export LANCER_BENCH_MESHES=$mesh
echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2) x $(nproc); load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for ((r = 0; r < repetitions; ++r)); do
  for i in "${!binaries[@]}"; do
    for row in bvh embree-medium; do
      [[ $row == embree-medium && $i -gt 0 ]] && continue  # Embree is the same library in both
      for threads in 1 2; do
        "${binaries[$i]}" --benchmark_filter="^build/$row/$mesh/threads:$threads/" \
          --benchmark_out="$results/${i}_${row}_${threads}_$r.json" --benchmark_out_format=json > /dev/null 2>&1
      done
    done
  done
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
/usr/bin/python3 - "$results" "${#binaries[@]}" <<'PY'
import glob, json, statistics, sys
folder, count = sys.argv[1], int(sys.argv[2])
rows = {}
for path in glob.glob(folder + "/*.json"):
    binary, row, threads, _ = path.rsplit("/", 1)[1][:-5].split("_")
    runs = [b for b in json.load(open(path))["benchmarks"] if b.get("run_type") == "iteration"]
    entry = rows.setdefault((binary, row, threads), {"fresh": [], "warm": [], "sah": [], "bytes": []})
    entry["fresh"].append(runs[0]["real_time"] / 1e3)
    entry["warm"] += [b["real_time"] / 1e3 for b in runs[1:]]
    if "sah_cost" in runs[0]:
        entry["sah"].append(runs[0]["sah_cost"])
    if "bytes_per_tri" in runs[0]:
        entry["bytes"].append(runs[0]["bytes_per_tri"])
med = lambda v: statistics.median(v) if v else None
print("| binary | accel | threads | fresh build s | warm build s | SAH cost | bytes/tri | MEDIUM/lancer fresh | MEDIUM/lancer warm |")
print("|---|---|---|---|---|---|---|---|---|")
for binary in map(str, range(count)):
    for row in ("bvh", "embree-medium"):
        for threads in ("1", "2"):
            e = rows.get((binary, row, threads))
            if not e: continue
            m = rows.get(("0", "embree-medium", threads))
            rf = med(m["fresh"]) / med(e["fresh"]) if m and row == "bvh" else None
            rw = med(m["warm"]) / med(e["warm"]) if m and row == "bvh" else None
            sah, size = med(e["sah"]), med(e["bytes"])
            print(f"| {binary} | {row} | {threads} | {med(e['fresh']):.3f} | {med(e['warm']):.3f} | "
                  f"{'-' if sah is None else f'{sah:.2f}'} | {'-' if size is None else f'{size:.1f}'} | "
                  f"{'-' if rf is None else f'{rf:.2f}'} | {'-' if rw is None else f'{rw:.2f}'} |")
PY
