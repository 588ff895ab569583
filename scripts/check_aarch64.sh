#!/usr/bin/env bash
# Checks that the library builds for ARM64 (aarch64), from an x86-64 Debian machine: every source of
# src/lancer, apps/lancer and the tests' support is compiled with Debian's cross compiler
# (g++-aarch64-linux-gnu, installed when missing), as the portable path builds them there (no
# x86-64-v3 copy, no x86 intrinsics). Debian 12 cannot install the arm64 builds of the libraries
# beside the host's without multiarch, so their headers are taken from the host (those used are the
# same on every architecture) and nothing is linked; on an ARM64 machine itself, build as on any
# other (docs/hardening.md). Usage: scripts/check_aarch64.sh [--syntax-only] [-jN]
set -euo pipefail
cd "$(dirname "$0")/.."

mode=(-c -O2 -o /dev/null)
jobs=$(nproc)
for argument in "$@"; do
  case $argument in
    --syntax-only) mode=(-fsyntax-only) ;;
    -j*) jobs=${argument#-j} ;;
    *) echo "check_aarch64: unknown argument $argument (--syntax-only, -jN)" >&2; exit 2 ;;
  esac
done

compiler=aarch64-linux-gnu-g++
if ! command -v "$compiler" >/dev/null; then
  echo "check_aarch64: installing g++-aarch64-linux-gnu" >&2
  sudo=""
  if [ "$(id -u)" != 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends g++-aarch64-linux-gnu >&2
fi

# The third-party headers the sources include, from the host: only these folders and files, so that
# the host's own C library headers (x86-64) never shadow the cross compiler's.
headers=$(mktemp -d)
trap 'rm -rf "$headers"' EXIT
for entry in fmt toml++ CLI freetype2 fontconfig OpenEXR Imath png.h pngconf.h pnglibconf.h zlib.h zconf.h \
             gif_lib.h gtest gmock jpeglib.h jerror.h jmorecfg.h webp; do
  [ -e "/usr/include/$entry" ] || { echo "check_aarch64: /usr/include/$entry missing: run scripts/setup.sh" >&2; exit 1; }
  ln -s "/usr/include/$entry" "$headers/$entry"
done
# libjpeg-turbo's configuration header sits in the host's architecture folder; its definitions are
# the same on ARM64 (8-bit samples, the same API), and nothing is linked.
ln -s /usr/include/x86_64-linux-gnu/jconfig.h "$headers/jconfig.h"
# CMake's definitions for a build with OpenEXR, without MPI and FFmpeg (their headers are per
# architecture; the video writer then builds its refusal).
flags=(-std=c++20 -Wall -Wextra -Wpedantic -Wshadow -Werror -Wno-psabi -DLANCER_HAVE_OPENEXR=1
       -DLANCER_VERSION=\"check\" -Isrc -Iapps/lancer -Itests -isystem "$headers" -isystem "$headers/freetype2"
       -isystem "$headers/OpenEXR" -isystem "$headers/Imath"
       -DLANCER_TEST_DATA_DIR=\"\" -DLANCER_SOURCE_DIR=\"\" -DLANCER_CLI_PATH=\"\")
# Anything x86 left unguarded shows up as an error; the x86-64-v3 copy must not be built here.
if "$compiler" -dM -E -x c++ /dev/null | grep -q "__x86_64__"; then
  echo "check_aarch64: $compiler does not target aarch64" >&2
  exit 1
fi

mapfile -t sources < <(find src/lancer apps/lancer tests/support -name '*.cpp' | sort)
log=$(mktemp)
trap 'rm -rf "$headers" "$log"' EXIT
printf '%s\n' "${sources[@]}" |
  xargs -P "$jobs" -I{} sh -c '"$0" "$@" {} 2>&1 || echo "check_aarch64: FAILED {}"' "$compiler" "${mode[@]}" "${flags[@]}" \
  >"$log"
if grep -q "check_aarch64: FAILED" "$log"; then
  cat "$log" >&2
  echo "check_aarch64: $(grep -c 'check_aarch64: FAILED' "$log") of ${#sources[@]} sources do not compile for aarch64" >&2
  exit 1
fi
[ ! -s "$log" ] || cat "$log" >&2
echo "check_aarch64: ${#sources[@]} sources compile for aarch64 ($("$compiler" -dumpversion), ${mode[*]})"
