#!/usr/bin/env bash
# The x86-64-v3 copies of the hot kernels (util/isa.hpp) must define no symbol that the baseline
# code could link to: every external symbol they define names the copy (its namespace x86_64_v3 or
# its tag isa::X86_64_V3). An inline function or template instance outside those (a std:: one, or a
# header's inline function left out of line) would be merged by the linker with the baseline one,
# and a CPU without AVX2 could then run the x86-64-v3 code. (DW.ref.__gxx_personality_v0 is data: the
# exception tables' pointer to the C++ runtime's personality routine, the same in every object.)
# Usage: kernel_symbols.sh OBJECTS (one argument, ';'-separated, or several)
set -euo pipefail
objects=()
for argument in "$@"; do
  IFS=';' read -r -a parts <<<"$argument"
  objects+=("${parts[@]}")
done
((${#objects[@]})) || { echo "kernel_symbols: no object files given" >&2; exit 1; }
status=0
for object in "${objects[@]}"; do
  [ -f "$object" ] || { echo "kernel_symbols: $object is missing (build the library first)" >&2; exit 1; }
  # nm: VALUE TYPE NAME, or TYPE NAME for weak undefined; defined external symbols only.
  stray=$(nm --defined-only --extern-only -C "$object" | cut -c18- | grep -v -e 'x86_64_v3' -e 'X86_64_V3' -e '^V DW\.ref\.__gxx_personality_v0$' || true)
  if [ -n "$stray" ]; then
    echo "kernel_symbols: $object defines symbols outside the x86-64-v3 copy:" >&2
    echo "$stray" >&2
    status=1
  fi
done
((status == 0)) && echo "kernel_symbols: ${#objects[@]} objects, every external symbol in the x86-64-v3 copy"
exit $status
