#!/usr/bin/env bash
# Fuzzes the pbrt-v3 scene importer with libFuzzer + ASan + UBSan for a fixed
# budget (default 60 s), seeded with the bundled .pbrt scenes and the pbrt
# scenes the tests write.
#
#   scripts/fuzz-pbrt.sh [seconds]
#   SAFEGI_FUZZ_RUNS=N SAFEGI_FUZZ_SEED=S scripts/fuzz-pbrt.sh   (a fixed number of inputs)
#   SAFEGI_FUZZ_SEEDS=DIR scripts/fuzz-pbrt.sh                    (more seed scenes, e.g. fetched ones)
#
# Builds in build-fuzz-pbrt/ (clang). A crash leaves its input in
# build-fuzz-pbrt/fuzz-artifacts/ and the script exits non-zero; turn every
# such input into a case of cpu_renderer/src/pbrt_import_test.cpp.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
build=${SAFEGI_FUZZ_BUILD_DIR:-$root/build-fuzz-pbrt}
jobs=${JOBS:-2}

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link" \
  -DSAFEGI_SANITIZE=ON -DSAFEGI_FUZZ=ON \
  -DSAFEGI_BUILD_TESTS=OFF -DSAFEGI_BUILD_BENCH=OFF -DSAFEGI_BUILD_GL=OFF >/dev/null
cmake --build "$build" -j"$jobs" --target safegi_pbrt_import_fuzzer

corpus="$build/fuzz-corpus"
artifacts="$build/fuzz-artifacts"
mkdir -p "$corpus" "$artifacts"
find "$root/examples" ${SAFEGI_FUZZ_SEEDS:+"$SAFEGI_FUZZ_SEEDS"} -type f -name '*.pbrt' -size -64k \
  -exec cp -t "$corpus" {} + 2>/dev/null || true
python3 "$root/bench/renderer/json_to_pbrt.py" "$root/examples/scenes/cornell-box/cornell-box.json" 4 out.exr \
  > "$corpus/cornell.pbrt"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
budget=(-max_total_time="$seconds")
if [[ -n "${SAFEGI_FUZZ_RUNS:-}" ]]; then
  budget=(-runs="$SAFEGI_FUZZ_RUNS" -seed="${SAFEGI_FUZZ_SEED:-1}")
fi
exec "$build/bin/safegi_pbrt_import_fuzzer" "${budget[@]}" -max_len=65536 -timeout=10 \
  -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts/" "$corpus"
