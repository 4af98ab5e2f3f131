#!/usr/bin/env bash
# Runs one of SafeGI's libFuzzer targets with ASan + UBSan for a fixed budget
# (default 60 s):
#
#   scripts/fuzz.sh compiler [seconds]   the whole safeglslc pipeline, seeded with
#                                        the example and golden-test shaders
#   scripts/fuzz.sh lsp [seconds]        safegi-lsp's engine (framing, JSON-RPC,
#                                        documents, requests), seeded with the
#                                        sessions in lsp/fuzz/seeds/
#   scripts/fuzz.sh pbrt [seconds]       the pbrt-v3 scene importer, seeded with the
#                                        bundled .pbrt scenes, the Cornell box
#                                        written as pbrt, and SAFEGI_FUZZ_SEEDS=DIR
#   SAFEGI_FUZZ_RUNS=N SAFEGI_FUZZ_SEED=S scripts/fuzz.sh <target>
#       a fixed number of inputs from a fixed seed instead of a time budget:
#       the same inputs every time, as CI needs.
#
# Builds in build-fuzz/ (clang, its own build directory, shared by the
# targets). A crash leaves its input in build-fuzz/fuzz-artifacts/<target>/
# and the script exits non-zero; turn every such input into a regression test
# (compiler: a golden case under testsuite/golden/cases/fuzz/; lsp: a case in
# lsp/src/server_test.cpp; pbrt: a case of cpu_renderer/src/pbrt/pbrt_import_test.cpp).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
target=${1:?usage: scripts/fuzz.sh compiler|lsp|pbrt [seconds]}
seconds=${2:-60}
build=${SAFEGI_FUZZ_BUILD_DIR:-$root/build-fuzz}
jobs=${JOBS:-2}

# The importer is the renderer's: only its target builds the renderer.
renderer=OFF
max_len=16384
case "$target" in
  compiler) executable=safegi_compile_fuzzer ;;
  lsp) executable=safegi_lsp_fuzzer ;;
  pbrt) executable=safegi_pbrt_import_fuzzer renderer=ON max_len=65536 ;;
  *) echo "fuzz.sh: unknown target '$target' (compiler, lsp or pbrt)" >&2; exit 2 ;;
esac

# -O1 -g1: the fuzzer's build is most of a CI fuzz run's time; -O1 compiles
# about 2.5x faster than -O2 -g and is what ASan recommends. A folder already
# configured for fuzzing (scripts/test.sh --sanitize's build-asan, which CI
# names in SAFEGI_FUZZ_BUILD_DIR) is built as it is, tests and all.
if ! grep -q '^SAFEGI_FUZZ:BOOL=ON$' "$build/CMakeCache.txt" 2>/dev/null; then
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link" \
  -DSAFEGI_SANITIZE=ON -DSAFEGI_FUZZ=ON \
  -DSAFEGI_BUILD_TESTS=OFF -DSAFEGI_BUILD_BENCH=OFF -DSAFEGI_BUILD_GL=OFF -DSAFEGI_BUILD_RENDERER=$renderer >/dev/null
fi
cmake --build "$build" -j"$jobs" --target "$executable"

corpus="$build/fuzz-corpus/$target"
artifacts="$build/fuzz-artifacts/$target"
mkdir -p "$corpus" "$artifacts"
# Seeds are copied, so libFuzzer may add to the corpus directory.
if [[ "$target" == compiler ]]; then
  find "$root/examples" "$root/testsuite/golden/cases" "$root/symbol_table/testdata" "$root/compiler/testdata" \
    -type f \( -name '*.vert' -o -name '*.frag' -o -name '*.geom' -o -name '*.comp' -o -name '*.tesc' \
    -o -name '*.tese' -o -name '*.sgl' -o -name '*.glsl' \) -exec cp -t "$corpus" {} + 2>/dev/null || true
elif [[ "$target" == lsp ]]; then
  cp -t "$corpus" "$root"/lsp/fuzz/seeds/*
else
  find "$root/examples" ${SAFEGI_FUZZ_SEEDS:+"$SAFEGI_FUZZ_SEEDS"} -type f -name '*.pbrt' -size -64k \
    -exec cp -t "$corpus" {} + 2>/dev/null || true
  python3 "$root/bench/renderer/json_to_pbrt.py" "$root/examples/scenes/cornell-box/cornell-box.json" 4 out.exr \
    > "$corpus/cornell.pbrt"
fi

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
budget=(-max_total_time="$seconds")
if [[ -n "${SAFEGI_FUZZ_RUNS:-}" ]]; then
  budget=(-runs="$SAFEGI_FUZZ_RUNS" -seed="${SAFEGI_FUZZ_SEED:-1}")
fi
exec "$build/bin/$executable" "${budget[@]}" -max_len="$max_len" -timeout=10 \
  -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts/" "$corpus"
