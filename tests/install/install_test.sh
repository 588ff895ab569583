#!/usr/bin/env bash
# `cmake --install` of a finished build into a temporary prefix, then what a user runs from there:
# P/bin/lancer --version, the manual in P/share/doc/lancer, the man pages and shell completion, and
# (when the build has the Python module) `import lancer` from another folder with PYTHONPATH at the
# installed package. Installs only: no rebuild.
# Usage: install_test.sh BUILD_DIR VERSION [PYTHON]
set -euo pipefail
build=$1 version=$2 python=${3:-}

prefix=$(mktemp -d)
elsewhere=$(mktemp -d)
# `cmake --install` rewrites BUILD_DIR/install_manifest.txt; a real install's manifest is put back.
manifest="$build/install_manifest.txt"
saved=""
if [ -f "$manifest" ]; then
  saved=$(mktemp)
  cp "$manifest" "$saved"
fi
cleanup() {
  rm -rf "$prefix" "$elsewhere"
  if [ -n "$saved" ]; then mv "$saved" "$manifest"; else rm -f "$manifest"; fi
}
trap cleanup EXIT

fail() {
  echo "install_test: $*" >&2
  exit 1
}

cmake --install "$build" --prefix "$prefix" >"$elsewhere/install.log" 2>&1 ||
  { cat "$elsewhere/install.log" >&2; fail "cmake --install failed"; }

[ -x "$prefix/bin/lancer" ] || fail "no $prefix/bin/lancer"
printed=$(cd "$elsewhere" && "$prefix/bin/lancer" --version)
[ "$printed" = "lancer $version" ] || fail "lancer --version printed '$printed', expected 'lancer $version'"
printed=$(cd "$elsewhere" && "$prefix/bin/lancer" -V)
[ "$printed" = "lancer $version" ] || fail "lancer -V printed '$printed', expected 'lancer $version'"
for page in rendering.md scene_file.md python.md LICENSE; do
  [ -f "$prefix/share/doc/lancer/$page" ] || fail "no $prefix/share/doc/lancer/$page"
done
# The man pages and the shell completion, where the build made them (packaging/CMakeLists.txt).
if [ -f "$build/packaging/man/lancer.1" ]; then
  for page in "$build"/packaging/man/*.1; do
    [ -f "$prefix/share/man/man1/$(basename "$page")" ] || fail "no $prefix/share/man/man1/$(basename "$page")"
  done
fi
if [ -d "$build/packaging/completion" ]; then
  for file in bash-completion/completions/lancer zsh/vendor-completions/_lancer fish/vendor_completions.d/lancer.fish; do
    [ -f "$prefix/share/$file" ] || fail "no $prefix/share/$file"
  done
fi

if [ -n "$python" ]; then
  # The folder the package went to, as install_package.cmake chose it for this prefix.
  init=$(find "$prefix" -path '*/lancer/__init__.py' | head -n 1)
  [ -n "$init" ] || fail "no lancer/__init__.py under $prefix"
  site=$(dirname "$(dirname "$init")")
  printed=$(cd "$elsewhere" && PYTHONPATH="$site" PYTHONDONTWRITEBYTECODE=1 "$python" -c \
    'import lancer, os; assert lancer.__file__.startswith(os.environ["PYTHONPATH"]), lancer.__file__; print(lancer.__version__)')
  [ "$printed" = "$version" ] || fail "lancer.__version__ is '$printed', expected '$version'"
  echo "install_test: package in ${site#"$prefix"/}"
fi
echo "install_test: lancer $version installed and run from $prefix"
