#!/usr/bin/env bash
# Installs the Debian packages lancer needs (only those missing), then configures build/ (Release;
# for any x86-64 CPU, the hot kernels also for x86-64-v3) and builds what a user runs: build/lancer
# and the Python module (build/python/lancer, for
# Debian's /usr/bin/python3: see python/CMakeLists.txt), not the tests nor the benchmarks
# (scripts/test.sh builds those). Pass extra CMake options after the script name, e.g.
#   scripts/setup.sh -DLANCER_PORTABLE=ON        scripts/setup.sh -DLANCER_PYTHON=OFF
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(g++ cmake ninja-build pkg-config libfmt-dev libpng-dev libgif-dev libfreetype-dev libfontconfig-dev fonts-dejavu-core libtomlplusplus-dev
          libcli11-dev libgtest-dev libbenchmark-dev
          python3-dev pybind11-dev python3-numpy python3-pytest python3-gmsh
          libopenmpi-dev openmpi-bin libopenexr-dev libjpeg62-turbo-dev libwebp-dev
          libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
          help2man dpkg-dev python3-venv python3-pip python3-setuptools python3-wheel
          qemu-user)
missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo=""
  if [ "$(id -u)" != 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build build -j"$(nproc)" --target programs
