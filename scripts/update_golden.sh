#!/usr/bin/env bash
# Regenerates every golden image from the current renderer. Only run it when a change of picture is
# intended, look at the new PNGs, and give the reason in the commit message. LANCER_BUILD_DIR picks
# the build tree (default build); other arguments go to ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${LANCER_BUILD_DIR:-build}
cmake --build "$build" -j"$(nproc)"
LANCER_UPDATE_GOLDEN=1 ctest --test-dir "$build" -L golden --output-on-failure "$@"
git status --short -- '*.png'
