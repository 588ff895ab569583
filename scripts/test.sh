#!/usr/bin/env bash
# Builds lancer (installing what is missing) with its tests and benchmarks, and runs every test. This
# is the README's test command and what CI runs first; each step prints its time.
set -euo pipefail
cd "$(dirname "$0")/.."
step_start=$SECONDS
begin() { step_start=$SECONDS; echo "=== test.sh: $1" >&2; }
end() { echo "=== test.sh: $1 done in $((SECONDS - step_start)) s" >&2; }

begin "set up and build lancer and its Python module (scripts/setup.sh)"
scripts/setup.sh
end "setup"
begin "build the tests and benchmarks"
cmake --build build -j"$(nproc)"
end "build"
begin "ctest"
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"
end "ctest"
