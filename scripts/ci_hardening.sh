#!/usr/bin/env bash
# Hardening checks, run by .ci/run after scripts/test.sh:
#   1. the whole test suite built with AddressSanitizer + UndefinedBehaviorSanitizer (LANCER_SANITIZE),
#      by clang, with the libFuzzer targets (LANCER_FUZZ) in the same build: the library is compiled
#      once for the suite, the fuzzers and clang-tidy's compile database;
#   2. the parallel renderer and image tile tests built with ThreadSanitizer (LANCER_TSAN);
#   3. every libFuzzer target for FUZZ_SECONDS (default 30) on its committed corpus, as many at a time
#      as there are cores (each fuzzer is one process on one core);
#   4. clang-tidy on src/ with the checks of .clang-tidy (must be clean): the sources changed since
#      the last whole clean pass (.ci/tidy-baseline) and those that include a header that changed;
#      `scripts/ci_hardening.sh tidy-baseline` records HEAD as such a pass (after TIDY_FULL=1 passed);
#   5. clang-format on the sources: every .cpp and .hpp as .clang-format has it (FORMAT_STRICT=0 makes
#      a difference a warning, for a local run).
# Installs what is missing with apt-get, like scripts/setup.sh. Build folders: build-hardening-asan
# (sanitizers, fuzzers, clang-tidy's database) and build-hardening-tsan.
# The Python module is left out of these builds (-DLANCER_PYTHON=OFF): an extension built with ASan,
# TSan or libFuzzer cannot be loaded into the uninstrumented /usr/bin/python3; scripts/test.sh tests it.
# Skip steps with SKIP="asan tsan fuzz tidy format" (any subset), e.g. for a quick local run.
set -euo pipefail
cd "$(dirname "$0")/.."

if [ "${1:-}" = tidy-baseline ]; then
  printf '%s\n%s\n' "$(git rev-parse HEAD)" "$(clang-tidy --version | grep -m1 -i version)" >.ci/tidy-baseline
  echo "ci_hardening: .ci/tidy-baseline is now $(git rev-parse --short HEAD); commit it" >&2
  exit 0
fi

# Seven targets, 30 s each: on two cores four rounds of 30 s, the two minutes four targets of 60 s took.
FUZZ_SECONDS=${FUZZ_SECONDS:-30}
FORMAT_STRICT=${FORMAT_STRICT:-1}
SKIP=${SKIP:-}
jobs=$(nproc)

packages=(g++ cmake ninja-build pkg-config libfmt-dev libpng-dev libgif-dev libtomlplusplus-dev libcli11-dev
          libfreetype-dev libfontconfig-dev fonts-dejavu-core libgtest-dev clang libclang-rt-14-dev clang-format
          clang-tidy libopenexr-dev)
missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if ((${#missing[@]})); then
  echo "ci_hardening: installing ${missing[*]}" >&2
  sudo=""
  if [ "$(id -u)" != 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

script_start=$SECONDS
step_start=$SECONDS
begin() { step_start=$SECONDS; echo "=== ci_hardening: $1" >&2; }
end() { echo "=== ci_hardening: $1 done in $((SECONDS - step_start)) s" >&2; }
skipped() { [[ " $SKIP " == *" $1 "* ]]; }

# Sanitizer reports must fail the run, with stacks that name the line.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1}
# The sanitizer builds carry line tables only (-g1): the reports' stacks still name every function,
# file and line, inlined frames included, and each file compiles in about a fifth less time
# (docs/hardening.md).
sanitizer_build_flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG")

# One clang build for the ASan + UBSan suite, the fuzzers (their coverage instrumentation,
# fuzzer-no-link, costs the suite little) and clang-tidy (clang's compile database, so that every
# flag is one clang-tidy understands).
shared=build-hardening-asan
configure_shared() {
  CC=clang CXX=clang++ cmake -S . -B "$shared" -G Ninja "${sanitizer_build_flags[@]}" -DLANCER_SANITIZE=ON \
        -DLANCER_FUZZ=ON -DLANCER_MPI=OFF -DLANCER_BUILD_BENCH=OFF -DLANCER_PYTHON=OFF >/dev/null
}

if ! skipped asan; then
  begin "ASan + UBSan build (clang, with the fuzzers) and the whole test suite"
  # Without MPI: LeakSanitizer reports Open MPI's own allocations in MPI_Init (libraries we do not
  # build), so the MPI path is tested by the normal build; this build checks that lancer says so
  # under mpirun instead (mpi_cli_test).
  configure_shared
  cmake --build "$shared" -j"$jobs"
  ctest --test-dir "$shared" --output-on-failure -j"$jobs"
  end "ASan + UBSan"
fi

if ! skipped tsan; then
  begin "ThreadSanitizer build and the parallel renderer / tile tests"
  cmake -S . -B build-hardening-tsan -G Ninja "${sanitizer_build_flags[@]}" -DLANCER_TSAN=ON \
        -DLANCER_BUILD_BENCH=OFF -DLANCER_PYTHON=OFF >/dev/null
  cmake --build build-hardening-tsan -j"$jobs" --target render_analytic_test sampler_test image_test
  # The tests that run the tiled renderer with several threads or paste tiles from threads.
  ctest --test-dir build-hardening-tsan --output-on-failure -j"$jobs" \
        -R '^(RenderAnalytic\.|Sampler\..*ThreadCount|Image\.Tiles)'
  end "ThreadSanitizer"
fi

if ! skipped fuzz; then
  begin "libFuzzer targets, ${FUZZ_SECONDS} s each on the committed corpus, $jobs at a time"
  configure_shared
  cmake --build "$shared" -j"$jobs" --target fuzzers
  # Scratch in memory where possible: the image writer fsyncs every file it writes.
  work=$(mktemp -d -p /dev/shm 2>/dev/null || mktemp -d)
  mkdir -p "$shared/artifacts"
  trap 'rm -rf "$work"' EXIT
  # One fuzzer: its exit status is the fuzzer's, its output in $work/TARGET.log.
  fuzz() {
    local target=$1 dictionary=()
    mkdir -p "$work/$target"
    if [ -f "fuzz/$target.dict" ]; then dictionary=(-dict="fuzz/$target.dict"); fi
    # New inputs go to the scratch folder (first), the committed corpus is only read. -timeout turns
    # a hang into a failure, -rss_limit_mb an unbounded allocation.
    TMPDIR="$work" "$shared/fuzz/fuzz_$target" "${dictionary[@]}" -max_total_time="$FUZZ_SECONDS" \
      -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$shared/artifacts/$target-" \
      "$work/$target" "fuzz/corpus/$target" 2>"$work/$target.log"
  }
  # As many fuzzers at a time as cores: each still runs FUZZ_SECONDS on a core of its own.
  targets=(msh_reader scene_loader image_writer pos_reader hdr_map exr_map gmsh_options)
  for ((first = 0; first < ${#targets[@]}; first += jobs)); do
    batch=("${targets[@]:first:jobs}")
    pids=()
    for target in "${batch[@]}"; do
      fuzz "$target" &
      pids+=($!)
    done
    failed=0
    for k in "${!batch[@]}"; do
      target=${batch[k]}
      if wait "${pids[k]}"; then
        grep -E '^(#[0-9]+[[:space:]]+DONE|stat::number_of_executed_units)' "$work/$target.log" | sed "s/^/$target: /" >&2 || true
      else
        tail -n 60 "$work/$target.log" >&2
        echo "ci_hardening: fuzz_$target failed; the input is in the log above (artifact $shared/artifacts/$target-*)" >&2
        failed=1
      fi
    done
    if ((failed)); then exit 1; fi
  done
  end "fuzzing"
fi

if ! skipped tidy; then
  begin "clang-tidy on src/ (checks in .clang-tidy)"
  if [ ! -f "$shared/compile_commands.json" ]; then configure_shared; fi
  # clang's compile database, so that every flag is one clang-tidy understands. Sources that did not
  # change since the commit in .ci/tidy-baseline (a tree clang-tidy passed whole, with the clang-tidy
  # version on its second line), and include no header that did, give the same verdict as then: the
  # step checks the others, each whole. A full pass when the baseline is missing or not in this
  # clone's history, when .clang-tidy or clang-tidy's version changed, when the shared build left no
  # dependency records, or with TIDY_FULL=1 (then write HEAD into .ci/tidy-baseline once it passes:
  # scripts/ci_hardening.sh tidy-baseline).
  mapfile -t sources < <(git ls-files 'src/*.cpp')
  baseline=$(sed -n 1p .ci/tidy-baseline 2>/dev/null || true)
  tidyVersion=$(clang-tidy --version | grep -m1 -i version)
  deps=$(ninja -C "$shared" -t deps 2>/dev/null || true)
  if [ "${TIDY_FULL:-0}" != 1 ] && [ -n "$baseline" ] && [ -n "$deps" ] &&
     git cat-file -e "$baseline^{commit}" 2>/dev/null && git diff --quiet "$baseline" -- .clang-tidy &&
     [ "$(sed -n 2p .ci/tidy-baseline)" == "$tidyVersion" ]; then
    mapfile -t changed < <(git diff --name-only "$baseline" -- src)
    # The dependency records: each object's source (its first dependency), then every header it
    # read. A source is checked when it or one of its headers changed.
    mapfile -t sources < <({ awk -v changed="${changed[*]}" '
      BEGIN { n = split(changed, list, " "); for (i = 1; i <= n; ++i) want[list[i]] = 1 }
      /^[^ ]/ { source = ""; next }
      /^    / { path = $1; sub(/^(\.\.\/)+/, "", path); if (source == "") source = path
                if ((path in want) && source ~ /^src\/.*\.cpp$/) hit[source] = 1 }
      END { for (s in hit) print s }' <<<"$deps"; for file in "${changed[@]}"; do
        if [[ $file == *.cpp && -f $file ]]; then echo "$file"; fi; done; } | sort -u)
    echo "ci_hardening: clang-tidy on the ${#sources[@]} sources that changed since $baseline or include a header that did" >&2
  else
    echo "ci_hardening: clang-tidy on every source (${#sources[@]})" >&2
  fi
  if ((${#sources[@]})); then
    run-clang-tidy -quiet -j "$jobs" -p "$shared" "${sources[@]/#/$PWD/}" >"$shared/tidy.log" 2>&1 || true
  else
    : >"$shared/tidy.log"
  fi
  if grep -E '(warning|error): ' "$shared/tidy.log" >&2; then
    echo "ci_hardening: clang-tidy found problems (above)" >&2
    exit 1
  fi
  end "clang-tidy"
fi

if ! skipped format; then
  begin "clang-format check"
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp')
  if ! clang-format --dry-run "${files[@]}" 2>"${TMPDIR:-/tmp}/lancer-format.log"; then :; fi
  unformatted=$(grep -c 'warning:' "${TMPDIR:-/tmp}/lancer-format.log" || true)
  if [ "$unformatted" != 0 ]; then
    echo "ci_hardening: $unformatted places differ from .clang-format in $(grep 'warning:' \
      "${TMPDIR:-/tmp}/lancer-format.log" | cut -d: -f1 | sort -u | wc -l) files; fix with:" >&2
    echo "  git ls-files '*.cpp' '*.hpp' | xargs clang-format -i" >&2
    if [ "$FORMAT_STRICT" = 1 ]; then exit 1; fi
  fi
  end "clang-format"
fi

echo "=== ci_hardening: all steps passed in $((SECONDS - script_start)) s" >&2
