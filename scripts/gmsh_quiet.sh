# Sourced by the fixture scripts: quiet COMMAND... runs gmsh (or anything), showing its output only
# when it fails or reports an error.
quiet() {
  local log
  log=$(mktemp)
  if ! "$@" >"$log" 2>&1 || grep -q '^Error' "$log"; then
    cat "$log" >&2
    rm -f "$log"
    return 1
  fi
  rm -f "$log"
}
