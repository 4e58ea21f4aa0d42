#!/usr/bin/env bash
# The sanitizer pass of `make test`: builds Fluence with clang++-16 and
# -fsanitize=address,undefined -fno-sanitize-recover=undefined (CMake option FLUENCE_SANITIZE) and
# runs the scene, delegate and apps (CLI) test suites through ctest (the ctest labels of
# tests/CMakeLists.txt). Every test process and every `fluence` process the CLI tests start write
# their AddressSanitizer, LeakSanitizer and UndefinedBehaviorSanitizer reports into one folder, and
# any report there fails the pass, even when a test passed anyway (a CLI test that expects a
# non-zero exit code, or one that interrupts `fluence`). Reports are printed, then the pass exits 1.
#
#   scripts/sanitizer_tests.sh
#
# Environment:
#   SANITIZE_BUILD_DIR  build folder (default build/asan); reports land in $SANITIZE_BUILD_DIR/sanitizer-reports
#   SANITIZE_LABELS     ctest -L regex of the suites to run (default ^(scene|delegate|apps)$)
#   SANITIZE_ARGS       more ctest arguments, e.g. "-R Instanced"
#   JOBS                build and ctest parallelism (default 2)
#   WERROR              ON: compiler warnings are errors (CMake FLUENCE_WERROR; `make test` sets it)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
root=$(pwd)

build=${SANITIZE_BUILD_DIR:-build/asan}
labels=${SANITIZE_LABELS:-'^(scene|delegate|apps)$'}
jobs=${JOBS:-2}
mkdir -p "$build"
build=$(cd "$build" && pwd)

clang=$(command -v clang++-16 || true)
if [[ -z "$clang" ]]; then
  echo "sanitize: clang++-16 not found (Debian: apt-get install clang-16 libclang-rt-16-dev)" >&2
  exit 1
fi
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)

# Let ccache reuse the sanitized objects across clones and build folders (as fuzz_smoke.sh does).
export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=true
start=$(date +%s)
cmake -S . -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DFLUENCE_SANITIZE=ON \
  -DFLUENCE_WERROR="${WERROR:-OFF}" -DCMAKE_CXX_COMPILER="$clang" >/dev/null
cmake --build "$build" -j "$jobs" --target fluence scene_tests delegate_tests apps_tests
built=$(date +%s)
echo "sanitize: built in $((built - start)) s"

reports="$build/sanitizer-reports"
rm -rf "$reports"
mkdir -p "$reports"
symbolizer=/usr/lib/llvm-16/bin/llvm-symbolizer
[[ -x "$symbolizer" ]] && export ASAN_SYMBOLIZER_PATH=$symbolizer
# Reports go to $reports/report.<pid> (log_path, one setting shared by both runtimes); exitcode 86
# is no exit code of `fluence`, so a CLI test never mistakes a report for the error it expects.
# new_delete_type_mismatch=0: OpenImageIO 2.4 (Debian's prebuilt, uninstrumented library) frees
# its TextureSystem inside TextureSystem::destroy with a sized delete of 1 byte
# for a 184-byte object, which ASan reports from every test that renders with a
# texture system; ASan cannot suppress that report per library. In Fluence's own code the usual
# cause, a delete through a base without a virtual destructor, is a -Wall warning (-Wdelete-non-virtual-dtor).
export ASAN_OPTIONS="log_path=$reports/report:exitcode=86:new_delete_type_mismatch=0:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1"
export UBSAN_OPTIONS="log_path=$reports/report:exitcode=86:print_stacktrace=1:halt_on_error=1"

status=0
(cd "$build" && ctest --output-on-failure -j "$jobs" -L "$labels" ${SANITIZE_ARGS:-}) || status=$?
echo "sanitize: tests ran in $(($(date +%s) - built)) s"

if compgen -G "$reports/*" >/dev/null; then
  for report in "$reports"/*; do
    echo "==== $report" >&2
    head -80 "$report" >&2
  done
  echo "sanitize: FAILED: $(ls "$reports" | wc -l) sanitizer report(s) in $reports" >&2
  exit 1
fi
if ((status != 0)); then
  echo "sanitize: FAILED: ctest exited with $status" >&2
  exit "$status"
fi
echo "sanitize: OK, no sanitizer reports"
