#!/usr/bin/env bash
# Fuzzes the whole safeglslc pipeline with libFuzzer + ASan + UBSan for a fixed
# budget (default 60 s), seeded with the example and golden-test shaders.
#
#   scripts/fuzz-compiler.sh [seconds]
#   SAFEGI_FUZZ_RUNS=N SAFEGI_FUZZ_SEED=S scripts/fuzz-compiler.sh
#       a fixed number of inputs from a fixed seed instead of a time budget:
#       the same inputs every time, as CI needs.
#
# Builds in build-fuzz/ (clang, its own build directory). A crash leaves its
# input in build-fuzz/fuzz-artifacts/ and the script exits non-zero; turn every
# such input into a regression case under testsuite/golden/cases/fuzz/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
build=${SAFEGI_FUZZ_BUILD_DIR:-$root/build-fuzz}
jobs=${JOBS:-2}

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link" \
  -DSAFEGI_SANITIZE=ON -DSAFEGI_FUZZ=ON \
  -DSAFEGI_BUILD_TESTS=OFF -DSAFEGI_BUILD_BENCH=OFF -DSAFEGI_BUILD_GL=OFF -DSAFEGI_BUILD_RENDERER=OFF >/dev/null
cmake --build "$build" -j"$jobs" --target safegi_compile_fuzzer

corpus="$build/fuzz-corpus"
artifacts="$build/fuzz-artifacts"
mkdir -p "$corpus" "$artifacts"
# Seeds: every shader we have (copied, so libFuzzer may add to the corpus dir).
find "$root/examples" "$root/testsuite/golden/cases" "$root/runtime_gl/testdata" "$root/compiler/testdata" \
  -type f \( -name '*.vert' -o -name '*.frag' -o -name '*.geom' -o -name '*.comp' -o -name '*.tesc' \
  -o -name '*.tese' -o -name '*.sgl' -o -name '*.glsl' \) -exec cp -t "$corpus" {} + 2>/dev/null || true

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
budget=(-max_total_time="$seconds")
if [[ -n "${SAFEGI_FUZZ_RUNS:-}" ]]; then
  budget=(-runs="$SAFEGI_FUZZ_RUNS" -seed="${SAFEGI_FUZZ_SEED:-1}")
fi
exec "$build/bin/safegi_compile_fuzzer" "${budget[@]}" -max_len=16384 -timeout=10 \
  -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts/" "$corpus"
