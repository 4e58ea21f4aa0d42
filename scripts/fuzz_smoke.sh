#!/usr/bin/env bash
# Builds the USD readers' libFuzzer targets (fuzz/), assembles their seed corpora and fuzzes the
# USDA reader for SECONDS (default 60), then the crate reader for CRATE_SECONDS (default SECONDS/2). Exits non-zero on any finding (crash, sanitizer report, uncaught exception
# other than usd::ParseError, timeout, out-of-memory, leak), printing the report and the path of
# the reproducer. `make test` runs it for 60 s; fuzz/README.md describes longer runs.
#
#   scripts/fuzz_smoke.sh [SECONDS]
#
# Environment:
#   FUZZ_BUILD_DIR  build folder (default build/fuzz); reproducers land in $FUZZ_BUILD_DIR/artifacts
#   FUZZ_CORPUS     keep the working corpus in this folder (default: a temporary folder, deleted)
#   FUZZ_SEED       libFuzzer's -seed (default 1: the same inputs in the same order each run)
#   FUZZ_JOBS       parallel fuzzing processes (default 1: in-process, one worker; the machine
#                   has 2 cores)
#   FUZZ_ARGS       more libFuzzer flags, e.g. "-use_value_profile=1 -only_ascii=1"
#   JOBS            build parallelism (default 2)
#   CRATE_SECONDS   how long to fuzz the crate reader (default SECONDS / 2; 0 skips it)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
root=$(pwd)

seconds=${1:-60}
[[ "$seconds" =~ ^[0-9]+$ ]] || { echo "usage: $0 [SECONDS]" >&2; exit 2; }
build=${FUZZ_BUILD_DIR:-build/fuzz}
mkdir -p "$build"
build=$(cd "$build" && pwd)
seed=${FUZZ_SEED:-1}
jobs=${FUZZ_JOBS:-1}

# ---- Build ---------------------------------------------------------------------------------------
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
clang=$(command -v clang++-16 || command -v clang++ || true)
if [[ -z "$clang" ]]; then
  echo "fuzz: clang++ not found (Debian: apt-get install clang-16 libclang-rt-16-dev)" >&2
  exit 1
fi
# A build folder configured with another compiler (an older clang) is configured afresh.
if [[ -f "$build/CMakeCache.txt" ]] &&
   ! grep -qx "CMAKE_CXX_COMPILER:[A-Z]*=$clang" "$build/CMakeCache.txt"; then
  rm -rf "$build/CMakeCache.txt" "$build/CMakeFiles"
fi
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S fuzz -B "$build" "${generator[@]}" -DCMAKE_CXX_COMPILER="$clang" >/dev/null
fi
# Let ccache reuse objects across clones and build folders (CI builds in a fresh clone): paths
# are hashed relative to the repository, and the -g build's working directory is not hashed.
export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=true
cmake --build "$build" -j "${JOBS:-2}" >"$build/build.log" 2>&1 || {
  cat "$build/build.log" >&2
  echo "fuzz: building the fuzzer failed" >&2
  exit 1
}
crate_seconds=${CRATE_SECONDS:-$((seconds / 2))}

# ---- Seed corpus ---------------------------------------------------------------------------------
# Every USD text layer of the tests, the samples and the shared real-world corpus (when present),
# plus every committed fuzz regression, copied under content-hash names into a folder that is
# rebuilt each run. Crate files are left out (the reader rejects them at the first byte), and so
# are layers over 64 KiB (-max_len): big geometry arrays only slow the fuzzer down.
max_len=65536
seeds="$build/seeds"
crate_seeds="$build/crate_seeds"
rm -rf "$seeds" "$crate_seeds"
mkdir -p "$seeds" "$crate_seeds"
sources=(tests/scene usd_samples)
[[ -d ../shared/usd_corpus ]] && sources+=(../shared/usd_corpus)
while IFS= read -r -d '' file; do
  if [[ $(head -c 8 "$file") == PXR-USDC ]]; then
    cp "$file" "$crate_seeds/$(sha1sum <"$file" | cut -c1-40)"
  else
    cp "$file" "$seeds/$(sha1sum <"$file" | cut -c1-40)"
  fi
done < <(find "${sources[@]}" -type f \( -name '*.usda' -o -name '*.sdf' -o -name '*.usd' -o -name '*.usdc' \) \
           -size -$((max_len + 1))c -print0 2>/dev/null)
if [[ -d tests/scene/fuzz_regressions ]]; then
  while IFS= read -r -d '' file; do
    cp "$file" "$seeds/$(sha1sum <"$file" | cut -c1-40)"
  done < <(find tests/scene/fuzz_regressions -type f ! -name 'README*' -print0)
fi
echo "fuzz: $(ls "$seeds" | wc -l) text and $(ls "$crate_seeds" | wc -l) crate seed inputs from ${sources[*]} tests/scene/fuzz_regressions"

# ---- Run -----------------------------------------------------------------------------------------
if [[ -n "${FUZZ_CORPUS:-}" ]]; then
  corpus_root=$FUZZ_CORPUS
  mkdir -p "$corpus_root"
else
  corpus_root=$(mktemp -d /tmp/fluence-fuzz-corpus.XXXXXX)
  trap 'rm -rf "$corpus_root"' EXIT
fi
artifacts="$build/artifacts"
mkdir -p "$artifacts"

symbolizer=/usr/lib/llvm-16/bin/llvm-symbolizer
[[ -x "$symbolizer" ]] && export ASAN_SYMBOLIZER_PATH=$symbolizer
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_stack_use_after_return=1:strict_string_checks=1:check_initialization_order=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

parallel=()
if ((jobs > 1)); then parallel=(-jobs="$jobs" -workers="$jobs"); fi

# fuzz NAME SEEDS SECONDS [libFuzzer flags...]: runs fuzz/NAME; exits non-zero on any finding.
fuzz() {
  local name=$1 seed_dir=$2 time=$3
  shift 3
  local fuzzer="$build/$name" corpus="$corpus_root/$name"
  mkdir -p "$corpus"
  local log="$build/fuzz-$name-$(date +%Y%m%d-%H%M%S).log"
  local before
  before=$(ls "$artifacts" | wc -l)
  echo "fuzz: running $fuzzer for ${time}s (seed $seed, log $log)"
  local start status=0
  start=$(date +%s)
  "$fuzzer" "$corpus" "$seed_dir" \
    -max_total_time="$time" -timeout=10 -rss_limit_mb=2048 -max_len=$max_len \
    -seed="$seed" -print_final_stats=1 \
    -artifact_prefix="$artifacts/" "${parallel[@]}" "$@" ${FUZZ_ARGS:-} >"$log" 2>&1 || status=$?
  local elapsed=$(($(date +%s) - start))

  # Summary: the last status line (executions, coverage, features, corpus) and the final stats.
  grep -E '^#[0-9]+' "$log" | tail -1 || true
  grep -E '^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb)' "$log" || true
  echo "fuzz: $name's corpus grew to $(ls "$corpus" | wc -l) inputs in ${elapsed}s"

  local new_artifacts
  new_artifacts=$(ls -t "$artifacts" | head -n $(($(ls "$artifacts" | wc -l) - before)))
  if [[ $status -ne 0 || -n "$new_artifacts" ]]; then
    echo "fuzz: FAILED (exit $status): the report follows" >&2
    # The report: from the first sanitizer/libFuzzer error line to the end.
    sed -n '/==[0-9]*==ERROR\|runtime error:\|deadly signal\|ALARM: working on the last Unit\|out-of-memory\|uncaught exception\|terminate called/,$p' "$log" | head -150 >&2
    for artifact in $new_artifacts; do
      echo "fuzz: reproducer: $artifacts/$artifact" >&2
    done
    echo "fuzz: reproduce with: $fuzzer $artifacts/<file>; minimise with: $fuzzer -minimize_crash=1 -runs=100000 $artifacts/<file>" >&2
    echo "fuzz: full log: $log" >&2
    exit 1
  fi
}

fuzz usda_fuzzer "$seeds" "$seconds" -dict=fuzz/usda.dict
((crate_seconds > 0)) && fuzz crate_fuzzer "$crate_seeds" "$crate_seconds"
echo "fuzz: OK, no findings"
