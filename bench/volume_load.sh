#!/usr/bin/env bash
# Load speed of a volume result (docs/volume.md): `lancer info` of the plate that
# bench/make_volume_load_data.py writes (3.5M tetrahedra, 20 displacement steps left in the file),
# best of REPS runs: wall and CPU seconds, peak RSS and file bytes / wall seconds. Run it under the
# build lock; a second lancer binary (e.g. the previous build) is measured in the same run.
#   bench/volume_load.sh LANCER [OTHER_LANCER] [FILE=bench/data/volume_plate.msh] [REPS=5]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
lancers=("$1")
shift
if [[ $# -gt 0 && -x $1 && $1 != *.msh ]]; then lancers+=("$1"); shift; fi
file=${1:-$here/data/volume_plate.msh}
reps=${2:-5}
[[ -f $file ]] || { echo "no $file: write it with /usr/bin/python3 bench/make_volume_load_data.py" >&2; exit 2; }
bytes=$(stat -c %s "$file")
cat "$file" > /dev/null  # in the page cache: the figures are of lancer, not of the disk
for lancer in "${lancers[@]}"; do
  best=""
  for _ in $(seq "$reps"); do
    line=$(/usr/bin/time -f "%e %U %S %M" "$lancer" info "$file" 2>&1 >/dev/null | tail -1)
    best=$(printf '%s\n%s\n' "$best" "$line" | awk 'NF == 4' | sort -n | head -1)
  done
  read -r wall user sys peak <<<"$best"
  awk -v l="$lancer" -v w="$wall" -v u="$user" -v s="$sys" -v p="$peak" -v b="$bytes" 'BEGIN {
    printf "%s info: best wall %.2f s (CPU %.2f s), %.0f MB/s, peak RSS %.0f MB\n", l, w, u + s, b / w / 1e6, p / 1024 }'
done
