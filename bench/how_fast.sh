#!/usr/bin/env bash
# The README's "How fast" table, remade in one run: each row's measurement taken by the script that
# took it before (bench/povray_compare.sh, bench/msh_load_vs_gmsh.sh, bench/run_accel_bench.sh,
# bench/animation_vs_renders.sh, bench/bvh_build_fresh.sh) or by the benchmark program behind it
# (bvh_refit_bench, first_pixel_embree_bench, `lancer render` under /usr/bin/time), one after the
# other. Prints the machine (CPU, cores, load average before and after) and the table in the README's
# markdown, ready to paste; every command and its raw output go to a log file.
#   bench/how_fast.sh [build-dir] [--quick] [--only ROWS] [--log FILE] [--meshes-from DIR]
#     build-dir        where lancer and the benchmarks are built (default build; configure with
#                      -DLANCER_BUILD_BENCH=ON; Embree from libembree-dev, Google Benchmark from
#                      libbenchmark-dev)
#     --quick          the whole pipeline on small meshes (10K and 100K triangles, a sphere of about
#                      12K for the reader, 6 animation frames, one repetition): a minute or two, to
#                      check the script, not figures to publish
#     --only ROWS      some rows only, e.g. --only povray,memory (demo, povray, reader, rays, refit,
#                      memory, animate, first_pixel, build; memory takes Embree's bytes from build)
#     --log FILE       the raw log (default bench/data/how_fast-DATE.log)
#     --meshes-from D  hard-link (or else symlink) the bench meshes from D when bench/data lacks them,
#                      before making them with gmsh from bench/geo/ (minutes at 4M triangles)
# Medians of 3 where a row repeats (the demo's trace, peak memory and time to first pixel, the
# animation, the Embree and refit benchmarks, the fresh builds); the reader against gmsh keeps its
# script's best of 5 (RUNS). Rows whose tool is missing (povray, gmsh, a benchmark not built) say so
# in the table. The script takes no lock: on a shared machine run it under the lock the others use,
# e.g. `flock /tmp/lancer-cpu.lock bench/how_fast.sh build`. Needs gmsh, povray, bc, /usr/bin/time
# (Debian: apt-get install gmsh povray bc time).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)

build=build
quick=0
only=
log=
store=
while (($#)); do
  case $1 in
    --quick) quick=1 ;;
    --only) only=${2:?--only needs rows}; shift ;;
    --log) log=${2:?--log needs a file}; shift ;;
    --meshes-from) store=${2:?--meshes-from needs a folder}; shift ;;
    -h|--help) sed -n '2,25p' "$0" | cut -c3-; exit 0 ;;
    -*) echo "how_fast.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) build=$1 ;;
  esac
  shift
done
[[ -d $build ]] || { echo "how_fast.sh: no build folder $build: configure and build first (see --help)" >&2; exit 2; }
build=$(cd "$build" && pwd)
lancer=$build/lancer
[[ -x $lancer ]] || { echo "how_fast.sh: $lancer is missing: cmake --build $build --target lancer_cli" >&2; exit 2; }
for tool in bc /usr/bin/time /usr/bin/python3; do
  command -v "$tool" > /dev/null || { echo "how_fast.sh: needs $tool (apt-get install bc time python3)" >&2; exit 2; }
done
[[ -z $store || -d $store ]] || { echo "how_fast.sh: --meshes-from $store is not a folder" >&2; exit 2; }

declare -A what cell
rows=(demo povray reader rays refit memory animate first_pixel build)  # the README's order
if [[ -n $only ]]; then
  for row in ${only//,/ }; do
    [[ " ${rows[*]} " == *" $row "* ]] || { echo "how_fast.sh: no row $row (rows: ${rows[*]})" >&2; exit 2; }
  done
  kept=()
  for row in "${rows[@]}"; do [[ ",$only," == *",$row,"* ]] && kept+=("$row"); done
  rows=("${kept[@]}")
fi
wanted() { [[ " ${rows[*]} " == *" $1 "* ]]; }

data=$here/data
mkdir -p "$data"
[[ -n $log ]] || log=$data/how_fast-$(date -u +%Y%m%d-%H%M%S).log
: > "$log" || { echo "how_fast.sh: cannot write the log $log" >&2; exit 2; }
log=$(cd "$(dirname "$log")" && pwd)/$(basename "$log")
work=$(mktemp -d /tmp/lancer-how-fast-XXXXXX)
trap 'rm -rf "$work"' EXIT

if ((quick)); then
  meshes=10k,100k   # end to end, memory, first pixel, rays and builds against Embree
  refit_mesh=100k
  repetitions=1
  frames=6
  reader_env=(RUNS=1 SPHERE_SIZE=0.054 "LANCER_BENCH_DATA=$data/quick")  # a sphere of about 12K triangles
else
  meshes=1m,4m
  refit_mesh=1m
  repetitions=3
  frames=36
  reader_env=(RUNS=5)
fi
unset LANCER_BENCH_DATA LANCER_BENCH_MESHES BENCH_FILTER  # the benchmarks read the meshes of bench/data
mesh_list=(${meshes//,/ })
threads=$(nproc)

note() { echo "how_fast: $*" >&2; }
say() { echo "$*" >> "$log"; }
# logged NAME COMMAND...: runs the command (stdout and stderr into $work/NAME.out and the log);
# returns its exit status.
logged() {
  local name=$1
  shift
  say ""
  say "=== $name: $* (load $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%H:%M:%S))"
  "$@" > "$work/$name.out" 2>&1
  local status=$?
  cat "$work/$name.out" >> "$log"
  ((status == 0)) || say "=== $name: exit status $status"
  return $status
}
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
calc() { awk "BEGIN { printf \"$1\", $2 }"; }  # calc FORMAT EXPRESSION
label() { echo "${1^^}"; }                       # 1m -> 1M
count() { awk -v n="$1" 'BEGIN { if (n >= 1e6) printf "%.2fM", n / 1e6; else if (n >= 1e3) printf "%.0fK", n / 1e3; else print n }'; }
# "A at 1M triangles, B at 4M" from values in the order of mesh_list
per_mesh() {
  local out= i=0 v
  for v in "$@"; do
    if ((i == 0)); then out="$v at $(label "${mesh_list[0]}") triangles"; else out+=", $v at $(label "${mesh_list[$i]}")"; fi
    ((++i))
  done
  echo "$out"
}
meshes_words() { local l=(); for m in "${mesh_list[@]}"; do l+=("$(label "$m")"); done; local s="${l[*]}"; echo "${s// / and }"; }

# The bench meshes: bench/data/bracket_<mesh>.msh (gmsh's ASCII, as bench/run_accel_bench.sh makes it)
# and bracket_<mesh>_bin.msh (MSH 4.1 binary, as bench/time_to_first_pixel.sh converts it).
mesh_file() {
  local name=$1 path=$data/$1
  [[ -f $path ]] && return 0
  if [[ -n $store && -f $store/$name ]]; then
    ln "$store/$name" "$path" 2> /dev/null || ln -s "$store/$name" "$path"
    return
  fi
  command -v gmsh > /dev/null || { note "$path is missing and gmsh is not installed"; return 1; }
  note "making $path with gmsh..."
  if [[ $name == *_bin.msh ]]; then
    mesh_file "${name%_bin.msh}.msh" || return 1
    logged "gmsh-$name" gmsh "$data/${name%_bin.msh}.msh" -save -bin -format msh41 -o "$work/$name" || return 1
  else
    logged "gmsh-$name" gmsh -2 "$here/geo/${name%.msh}.geo" -o "$work/$name" || return 1
  fi
  mv "$work/$name" "$path"
}

missing() { echo "not measured: $1 (see the log)"; }
bench_tool() {  # bench_tool NAME: the path of a benchmark program, or a failure when it is not built
  [[ -x $build/bench/$1 ]] && { echo "$build/bench/$1"; return 0; }
  say "missing $build/bench/$1 (configure with -DLANCER_BUILD_BENCH=ON; Embree: libembree-dev)"
  return 1
}
embree_version=$(dpkg-query -W -f='${Version}' libembree3-3 2> /dev/null | sed -E 's/^([0-9]+\.[0-9]+).*/\1/')
embree_version=${embree_version:-3}

# --- the demo's trace time, 2 and 1 threads (the summary line's `trace`) ---
row_demo() {
  local t r line faces=0 size= samples= t2=() t1=()
  for ((r = 0; r < repetitions; ++r)); do
    for t in 2 1; do
      logged "demo-$t-$r" "$lancer" render "$root/examples/demo.toml" -o "$work/demo.png" --accel bvh --threads "$t" || return 1
      line=$(grep -E ' faces, .* trace [0-9.]+ s' "$work/demo-$t-$r.out" | tail -1)
      [[ -n $line ]] || return 1
      read -r size faces samples < <(sed -nE 's/.*: ([0-9]+x[0-9]+), ([0-9]+) faces, ([0-9.]+) samples\/pixel.*/\1 \2 \3/p' <<< "$line")
      if ((t == 2)); then t2+=("$(sed -nE 's/.*trace ([0-9.]+) s.*/\1/p' <<< "$line")"); else t1+=("$(sed -nE 's/.*trace ([0-9.]+) s.*/\1/p' <<< "$line")"); fi
    done
  done
  what[demo]="\`examples/demo.toml\`, $size, $(calc %g "$samples") samples per pixel, $(count "$faces") faces (BVH)"
  cell[demo]="$(calc %.2f "$(median "${t2[@]}")") s of tracing on 2 threads ($(calc %.2f "$(median "${t1[@]}")") s on 1)"
}

# --- end to end against POV-Ray (bench/povray_compare.sh: one run per mesh) ---
row_povray() {
  local version ratios=() m r
  version=$(povray --version 2>&1 | sed -nE 's/^POV-Ray ([0-9]+\.[0-9]+).*/\1/p' | head -1)
  what[povray]="\`lancer render\` end to end against POV-Ray ${version:-3.7} (800x600, 4 samples, one light with shadows, $threads threads)"
  if command -v povray > /dev/null; then
    bench_tool pov_scene_writer > /dev/null || { cell[povray]=$(missing "pov_scene_writer not built"); return 0; }
  fi
  logged povray "$here/povray_compare.sh" "$build" "$meshes" 800x600 || return 1
  if grep -q 'povray not installed' "$work/povray.out"; then
    cell[povray]="not measured: POV-Ray is not installed (apt-get install povray)"
    return 0
  fi
  for m in "${mesh_list[@]}"; do
    r=$(awk -F'|' -v m="$m" '{ gsub(/ /, "", $2) } $2 == m { gsub(/ /, "", $10); print $10 }' "$work/povray.out")
    [[ -n $r ]] || return 1
    ratios+=("${r}x")
  done
  ratios[0]="${ratios[0]} faster"
  cell[povray]=$(per_mesh "${ratios[@]}")
}

# --- the reader against gmsh (bench/msh_load_vs_gmsh.sh: CPU time, best of its RUNS) ---
row_reader() {
  local version triangles lo hi
  version=$(gmsh --version 2>&1 | sed -nE 's/^([0-9]+\.[0-9]+).*/\1/p' | head -1)
  what[reader]="reading a mesh against gmsh ${version:-4} parsing it (CPU time)"
  bench_tool msh_load_bench > /dev/null || { cell[reader]=$(missing "msh_load_bench not built"); return 0; }
  logged reader env "${reader_env[@]}" "$here/msh_load_vs_gmsh.sh" "$build" || return 1
  if grep -q 'gmsh is not installed' "$work/reader.out"; then
    cell[reader]="not measured: gmsh is not installed (apt-get install gmsh)"
    return 0
  fi
  triangles=$(sed -nE 's/^mesh: ([0-9]+) triangles.*/\1/p' "$work/reader.out")
  [[ -n $triangles ]] || return 1
  what[reader]="reading a $(count "$triangles")-triangle mesh against gmsh ${version:-4} parsing it (CPU time)"
  # Rows "MSH4.1-binary 53M | gmsh wall, cpu | lancer wall, cpu | ratio wall, cpu, cpu less start-up".
  read -r lo hi < <(awk '$1 ~ /^MSH/ { r = $11; sub(/x$/, "", r); f = $1; sub(/^MSH/, "MSH ", f); sub(/-/, " ", f)
      if (lo == "" || r + 0 < lo + 0) { lo = r; flo = f } if (hi == "" || r + 0 > hi + 0) { hi = r; fhi = f } }
    END { if (lo != "") printf "%.0fx (%s)\t%.0fx (%s)\n", lo, flo, hi, fhi }' "$work/reader.out" | tr ' \t' '~ ')
  [[ -n $lo ]] || return 1
  cell[reader]="${lo//\~/ } to ${hi//\~/ } faster"
}

# --- single rays against Embree (bench/run_accel_bench.sh, 1 thread, medians of 3 in one process) ---
row_rays() {
  local m values
  what[rays]="single rays on the default BVH against Embree $embree_version, 1 thread: primary / shadow / incoherent"
  bench_tool embree_compare_bench > /dev/null || { cell[rays]=$(missing "embree_compare_bench not built"); return 0; }
  BENCH_FILTER='^trace/(bvh|embree-high)/[^/]+/[a-z]+/threads:1/' logged rays "$here/run_accel_bench.sh" "$build" "$meshes" || return 1
  local parts=()
  for m in "${mesh_list[@]}"; do
    # "| mesh | rays | threads | bvh | kd | kd-median | embree | default/Embree (wall) | ..." of the throughput table
    values=$(awk -F'|' -v m="$m" '/^## Ray throughput/ { on = 1; next } /^## / { on = 0 }
      on { for (i = 2; i <= 4; ++i) gsub(/ /, "", $i); gsub(/ /, "", $9) }
      on && $2 == m && $4 == "1" { r[$3] = $9 }
      END { if (r["primary"] != "" && r["shadow"] != "" && r["incoherent"] != "") printf "%s / %s / %sx", r["primary"], r["shadow"], r["incoherent"] }' "$work/rays.out")
    [[ -n $values ]] || return 1
    parts+=("$values")
  done
  cell[rays]=$(per_mesh "${parts[@]}")
}

# --- refit against rebuild of a warped mesh (bvh_refit_bench, 1 thread, medians of 3) ---
row_refit() {
  local bench ratio
  what[refit]="refitting the BVH of a warped $(label "$refit_mesh")-triangle mesh against rebuilding it"
  bench=$(bench_tool bvh_refit_bench) || { cell[refit]=$(missing "bvh_refit_bench not built"); return 0; }
  LANCER_BENCH_MESHES=$refit_mesh logged refit "$bench" --benchmark_out="$work/refit.json" --benchmark_out_format=json || return 1
  ratio=$(/usr/bin/python3 - "$work/refit.json" "$refit_mesh" <<'PY'
import json, statistics, sys
runs = json.load(open(sys.argv[1]))["benchmarks"]
def ms(kind):
    return statistics.median(b["real_time"] for b in runs if b.get("run_type") == "iteration"
                             and b["run_name"].startswith(f"{kind}/bvh/{sys.argv[2]}/threads:1/"))
print(f"{ms('refit') / ms('rebuild'):.2f}")
PY
  ) || return 1
  cell[refit]="${ratio}x the time"
}

# --- peak memory and time to first pixel of `lancer render` (MSH 4.1 binary, 800x600, 4 samples, 2 threads) ---
declare -A peak_kib first_pixel faces_of
renders() {
  local r m line
  declare -gA peaks=() firsts=()
  for ((r = 0; r < repetitions; ++r)); do
    for m in "${mesh_list[@]}"; do
      logged "render-$m-$r" /usr/bin/time -f 'peak %M KiB' "$lancer" render "$data/bracket_${m}_bin.msh" \
        -o "$work/render.png" --width 800 --height 600 --samples 4 --threads 2 || return 1
      line=$(grep -E ' faces, .*load [0-9.]+ s, build [0-9.]+ s' "$work/render-$m-$r.out" | tail -1)
      [[ -n $line ]] || return 1
      faces_of[$m]=$(sed -nE 's/.*, ([0-9]+) faces,.*/\1/p' <<< "$line")
      peaks[$m]+=" $(sed -nE 's/^peak ([0-9]+) KiB$/\1/p' "$work/render-$m-$r.out")"
      firsts[$m]+=" $(sed -nE 's/.*load ([0-9.]+) s, build ([0-9.]+) s.*/\1 \2/p' <<< "$line" | awk '{ print $1 + $2 }')"
    done
  done
  for m in "${mesh_list[@]}"; do
    peak_kib[$m]=$(median ${peaks[$m]})
    first_pixel[$m]=$(median ${firsts[$m]})
  done
}

# --- fresh builds against Embree MEDIUM (bench/bvh_build_fresh.sh, medians of its repetitions) ---
declare -A fresh_ratio_1 fresh_ratio_2 embree_bytes
row_build() {
  local m bench
  what[build]="the BVH build against Embree $embree_version's MEDIUM build, each the first of a fresh process, 2 threads"
  bench=$(bench_tool embree_compare_bench) || { cell[build]=$(missing "embree_compare_bench not built"); return 0; }
  local two=() one=()
  for m in "${mesh_list[@]}"; do
    logged "build-$m" "$here/bvh_build_fresh.sh" "$m" "$repetitions" "$bench" || return 1
    # "| binary | accel | threads | fresh | warm | SAH | bytes/tri | MEDIUM/lancer fresh | warm |"
    fresh_ratio_1[$m]=$(awk -F'|' '{ for (i = 2; i <= 10; ++i) gsub(/ /, "", $i) } $2 == "0" && $3 == "bvh" && $4 == "1" { print $9 }' "$work/build-$m.out")
    fresh_ratio_2[$m]=$(awk -F'|' '{ for (i = 2; i <= 10; ++i) gsub(/ /, "", $i) } $2 == "0" && $3 == "bvh" && $4 == "2" { print $9 }' "$work/build-$m.out")
    embree_bytes[$m]=$(awk -F'|' '{ for (i = 2; i <= 10; ++i) gsub(/ /, "", $i) } $2 == "0" && $3 == "embree-medium" && $4 == "2" { print $8 }' "$work/build-$m.out")
    [[ -n ${fresh_ratio_1[$m]} && -n ${fresh_ratio_2[$m]} ]] || return 1
    two+=("${fresh_ratio_2[$m]}x")
    one+=("${fresh_ratio_1[$m]}x")
  done
  two[0]="${two[0]} the speed"
  local ones="${one[*]}"
  cell[build]="$(per_mesh "${two[@]}") (1 thread: ${ones// /, })"
}

row_memory() {
  local m values=() embree=()
  what[memory]="peak memory of \`lancer render\` at $(meshes_words) triangles"
  renders || return 1
  for m in "${mesh_list[@]}"; do
    values+=("$(calc %.0f "${peak_kib[$m]} * 1024 / ${faces_of[$m]}")")
    [[ -n ${embree_bytes[$m]:-} ]] && embree+=("$(calc %.0f "${embree_bytes[$m]}")")
  done
  local list="${values[*]}"
  cell[memory]="${list// / and } bytes per triangle"
  if ((${#embree[@]})); then  # one figure when the meshes agree, else one a mesh
    local sizes="${embree[*]}"
    [[ $(printf '%s\n' "${embree[@]}" | sort -u | wc -l) == 1 ]] && sizes=${embree[0]}
    cell[memory]+=" (Embree's BVH alone: ${sizes// / and })"
  fi
}

row_first_pixel() {
  local m bench medium parts=()
  what[first_pixel]="time to first pixel of \`lancer render\` (load and build, 2 threads) against Embree $embree_version's MEDIUM build alone"
  bench=$(bench_tool first_pixel_embree_bench) || { cell[first_pixel]=$(missing "first_pixel_embree_bench not built"); return 0; }
  [[ -n ${first_pixel[${mesh_list[0]}]:-} ]] || renders || return 1
  for m in "${mesh_list[@]}"; do
    logged "first-pixel-$m" "$bench" "$data/bracket_${m}_bin.msh" "$repetitions" || return 1
    medium=$(/usr/bin/python3 -c '
import json, sys
for line in open(sys.argv[1]):
    line = line.strip()
    if line.startswith("{"):
        r = json.loads(line)
        if r["stage"] == "embree-medium build" and r["threads"] == 2: print(r["seconds"])' "$work/first-pixel-$m.out")
    [[ -n $medium ]] || return 1
    parts+=("$(calc %.2f "${first_pixel[$m]} / $medium")x")
  done
  parts[0]="${parts[0]} the time"
  cell[first_pixel]=$(per_mesh "${parts[@]}")
}

# --- `lancer animate` against one render per frame (bench/animation_vs_renders.sh, CPU, medians) ---
row_animate() {
  local r animate=() renders=()
  what[animate]="\`lancer animate\` against one render per frame ($frames frames)"
  for ((r = 0; r < repetitions; ++r)); do
    (cd "$root" && logged "animate-$r" "$here/animation_vs_renders.sh" "$lancer" "$frames" 2) || return 1
    animate+=("$(sed -nE 's/^animate -> numbered PNGs .*cpu +([0-9.]+) s.*/\1/p' "$work/animate-$r.out")")
    renders+=("$(sed -nE 's/^[0-9]+ x render -> PNG .*cpu +([0-9.]+) s.*/\1/p' "$work/animate-$r.out")")
    [[ -n ${animate[-1]} && -n ${renders[-1]} ]] || return 1
  done
  local saving
  saving=$(calc %.0f "100 * (1 - $(median "${animate[@]}") / $(median "${renders[@]}"))")
  if ((saving >= 0)); then
    cell[animate]="$saving% less CPU: the scene is loaded and the tree built once"
  else
    cell[animate]="$((-saving))% more CPU than separate renders"
  fi
}

cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')
commit=$(git -C "$root" rev-parse --short HEAD 2> /dev/null)$(git -C "$root" diff --quiet HEAD 2> /dev/null || echo ' with changes')
say "how_fast.sh $( ((quick)) && echo --quick) build=$build rows=${rows[*]} meshes=$meshes repetitions=$repetitions"
say "lancer $commit; CPU: $cpu x $threads"

# The meshes first (none is timed), each row's own.
needed=()
for m in "${mesh_list[@]}"; do
  { wanted povray || wanted rays || wanted build; } && needed+=("bracket_$m.msh")
  { wanted memory || wanted first_pixel; } && needed+=("bracket_${m}_bin.msh")
done
wanted refit && needed+=("bracket_$refit_mesh.msh")
for name in "${needed[@]}"; do
  mesh_file "$name" || note "$data/$name could not be made: the rows that need it fail"
done

load_before=$(cut -d' ' -f1-3 /proc/loadavg)
say "load before: $load_before"
failed=0
# The build row runs before the memory row: it takes Embree's bytes a triangle from it.
for row in demo povray reader rays refit build memory first_pixel animate; do
  wanted "$row" || continue
  note "$row..."
  if ! "row_$row"; then
    cell[$row]=$(missing "the measurement failed")
    failed=1
  fi
done
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
say ""
say "load after: $load_after"

echo "CPU: $cpu x $threads ($(nproc --all) in the machine); lancer $commit"
echo "load average before: $load_before; after: $load_after"
((quick)) && echo "(--quick: small meshes and one repetition, to check the pipeline; not figures to publish)"
echo
echo "| what | lancer |"
echo "|---|---|"
for row in "${rows[@]}"; do
  echo "| ${what[$row]:-$row} | ${cell[$row]} |"
done
echo
echo "raw output: $log"
exit $failed
