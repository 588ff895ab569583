#!/usr/bin/env bash
# The packages made from a finished build, unpacked or installed in temporary folders and run from
# another folder; nothing is compiled (the build folder is reused) and nothing is installed as root.
#   deb:   `cpack -G DEB` makes lancer_VERSION_ARCH.deb; `dpkg-deb -I` lists its Depends (the Debian
#          runtime packages, python3, numpy); `dpkg-deb -x` unpacks it, then usr/bin/lancer runs and
#          usr/lib/python3/dist-packages has the package that /usr/bin/python3 imports; the man pages
#          and completion are where man and the shells look.
#   wheel: `pip install --no-build-isolation --no-index .` in a venv made with --system-site-packages,
#          setup.py pointed at the build folder (LANCER_CMAKE_BUILD_DIR): `lancer` is on the venv's PATH
#          and `import lancer` works from any folder; without cmake, ninja and c++ on PATH pip fails
#          with one line naming them. Run on a copy of the files setup.py reads, so that the source
#          tree is not written to.
# A missing tool (dpkg-deb, dpkg-shlibdeps; python3-venv, pip, setuptools, wheel) skips with exit 77.
# Usage: package_test.sh deb|wheel SOURCE_DIR BUILD_DIR VERSION [PYTHON]
set -euo pipefail
mode=$1 source=$2 build=$3 version=$4 python=${5:-}

fail() {
  echo "package_test $mode: $*" >&2
  exit 1
}
skip() {
  echo "package_test $mode: skipped: $*" >&2
  exit 77
}

work=$(mktemp -d)
elsewhere=$work/elsewhere
mkdir "$elsewhere"
# cpack writes BUILD_DIR/install_manifest.txt, as `cmake --install` does; a real install's is put back.
manifest="$build/install_manifest.txt"
saved=""
if [ -f "$manifest" ]; then
  saved=$work/install_manifest.txt
  cp "$manifest" "$saved"
fi
cleanup() {
  if [ -n "$saved" ]; then cp "$saved" "$manifest"; elif [ "$mode" = deb ]; then rm -f "$manifest"; fi
  rm -rf "$work"
}
trap cleanup EXIT

# `import lancer` by PYTHON from another folder, from the package under SITE: prints its version.
import_from() {
  local python=$1 site=$2
  (cd "$elsewhere" && PYTHONDONTWRITEBYTECODE=1 SITE="$site" "$python" -c \
    'import lancer, os; assert lancer.__file__.startswith(os.environ["SITE"]), lancer.__file__; print(lancer.__version__)')
}
mesh=$source/tests/data/msh/cube_hex8_v41_ascii.msh

case $mode in
deb)
  for tool in cpack dpkg-deb dpkg-shlibdeps; do
    command -v "$tool" >/dev/null || skip "no $tool (Debian: apt install dpkg-dev; scripts/setup.sh does)"
  done
  (cd "$build" && cpack -G DEB -B "$work/package") >"$work/cpack.log" 2>&1 ||
    { cat "$work/cpack.log" >&2; fail "cpack -G DEB failed"; }
  arch=$(dpkg --print-architecture)
  deb=$work/package/lancer_${version}_${arch}.deb
  [ -f "$deb" ] || fail "cpack made no $deb: $(ls "$work/package")"
  [ "$(dpkg-deb -f "$deb" Package)" = lancer ] || fail "the package is not named lancer"
  [ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || fail "the package's version is not $version"
  depends=$(dpkg-deb -f "$deb" Depends)
  # The packages named in Depends, without their versions.
  depends_names=$(tr ',' '\n' <<<"$depends" | sed -E 's/^ +//; s/[ (].*//')
  for needed in libc6 libstdc++6 libpng16-16 libfreetype6 fonts-dejavu-core; do
    grep -qxF "$needed" <<<"$depends_names" || fail "Depends lacks $needed: $depends"
  done
  # FFmpeg's libraries are loaded with dlopen when a video is written: Recommends names them.
  if grep -q '^LANCER_FFMPEG:BOOL=ON' "$build/CMakeCache.txt"; then
    recommends=$(dpkg-deb -f "$deb" Recommends)
    for needed in libavcodec libavformat libavutil libswscale; do
      grep -qE "(^|, )$needed[0-9]+(,|$)" <<<"$recommends" || fail "Recommends lacks $needed: '$recommends'"
    done
  fi
  root=$work/root
  dpkg-deb -x "$deb" "$root"
  [ -z "$(find "$root" -mindepth 1 -maxdepth 1 ! -name usr)" ] || fail "the package installs outside /usr: $(ls "$root")"
  printed=$(cd "$elsewhere" && "$root/usr/bin/lancer" --version)
  [ "$printed" = "lancer $version" ] || fail "usr/bin/lancer --version printed '$printed'"
  (cd "$elsewhere" && "$root/usr/bin/lancer" info "$mesh" >/dev/null) || fail "usr/bin/lancer info failed"
  for file in share/man/man1/lancer.1 share/man/man1/lancer-render.1 share/bash-completion/completions/lancer \
    share/zsh/vendor-completions/_lancer share/fish/vendor_completions.d/lancer.fish share/doc/lancer/LICENSE; do
    [ -f "$root/usr/$file" ] || fail "no /usr/$file in the package"
  done
  if [ -n "$python" ]; then
    for needed in python3 python3-numpy; do
      grep -qxF "$needed" <<<"$depends_names" || fail "Depends lacks $needed: $depends"
    done
    dpkg-deb -I "$deb" postinst | grep -q 'py3compile -p lancer' || fail "the package's postinst does not byte-compile the package"
    site=$root/usr/lib/python3/dist-packages
    [ -f "$site/lancer/__init__.py" ] || fail "no /usr/lib/python3/dist-packages/lancer in the package"
    printed=$(PYTHONPATH=$site import_from "$python" "$site") || fail "$python could not import lancer from $site"
    [ "$printed" = "$version" ] || fail "lancer.__version__ is '$printed', expected '$version'"
  fi
  echo "package_test deb: $(basename "$deb"), $(stat -c %s "$deb") bytes; Depends: $depends"
  ;;
wheel)
  [ -n "$python" ] || skip "the build has no Python module"
  "$python" -c 'import setuptools, wheel, ensurepip, pip' 2>/dev/null ||
    skip "$python lacks venv, pip, setuptools or wheel (Debian: apt install python3-venv python3-pip python3-setuptools python3-wheel; scripts/setup.sh does)"
  copy=$work/source
  mkdir -p "$copy/python"
  cp "$source/pyproject.toml" "$source/setup.py" "$source/CMakeLists.txt" "$source/README.md" "$source/LICENSE" "$copy/"
  cp -r "$source/python/lancer" "$copy/python/"
  rm -rf "$copy/python/lancer/__pycache__"
  "$python" -m venv --system-site-packages "$work/venv"
  (cd "$copy" && LANCER_CMAKE_BUILD_DIR=$build PIP_NO_CACHE_DIR=1 PIP_DISABLE_PIP_VERSION_CHECK=1 \
    "$work/venv/bin/pip" install --no-build-isolation --no-index . >"$work/pip.log" 2>&1) ||
    { cat "$work/pip.log" >&2; fail "pip install failed"; }
  [ -x "$work/venv/bin/lancer" ] || fail "pip installed no bin/lancer in the venv"
  # Without the build tools (an empty PATH: no cmake, ninja nor c++), one line says what to install.
  if (cd "$copy" && env -u LANCER_CMAKE_BUILD_DIR PATH=/nonexistent PIP_NO_CACHE_DIR=1 \
    "$work/venv/bin/pip" wheel --no-build-isolation --no-index --no-deps -w "$work/wheels" . >"$work/pip-no-tools.log" 2>&1); then
    fail "pip built a wheel without cmake, ninja or a compiler on PATH"
  fi
  grep -q 'lancer: cannot build: cmake, ninja, a C++ compiler (c++) not found; install them' "$work/pip-no-tools.log" ||
    { cat "$work/pip-no-tools.log" >&2; fail "pip without the build tools did not say which are missing"; }
  printed=$(cd "$elsewhere" && PATH=$work/venv/bin:$PATH && command -v lancer && lancer --version)
  [ "$printed" = "$work/venv/bin/lancer"$'\n'"lancer $version" ] || fail "lancer on the venv's PATH printed '$printed'"
  (cd "$elsewhere" && "$work/venv/bin/lancer" info "$mesh" >/dev/null) || fail "the venv's lancer info failed"
  site=$("$work/venv/bin/python" -c 'import sysconfig; print(sysconfig.get_path("platlib"))')
  printed=$(import_from "$work/venv/bin/python" "$site") || fail "the venv's python could not import lancer from $site"
  [ "$printed" = "$version" ] || fail "lancer.__version__ is '$printed', expected '$version'"
  (cd "$elsewhere" && "$work/venv/bin/pip" uninstall -y lancer >/dev/null 2>&1) || fail "pip uninstall failed"
  [ ! -e "$work/venv/bin/lancer" ] || fail "pip uninstall left bin/lancer"
  echo "package_test wheel: pip installed lancer $version into a venv: bin/lancer and ${site#"$work"/}/lancer"
  ;;
*) fail "unknown mode '$mode' (deb or wheel)" ;;
esac
