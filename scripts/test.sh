#!/usr/bin/env bash
# The test command: installs dependencies, builds, and runs the whole test suite.
#   scripts/test.sh               Release build + every ctest test
#   scripts/test.sh --sanitize    also rebuilds the compiler under ASan+UBSan and runs its tests there
#   SAFEGI_WERROR=ON scripts/test.sh   a compiler warning fails the build (CI; both passes, GCC and Clang)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
sanitize=0
[[ "${1:-}" == "--sanitize" || -n "${SAFEGI_SANITIZE_TESTS:-}" ]] && sanitize=1

"$root/scripts/install-deps.sh"
jobs=${SAFEGI_JOBS:-$(nproc)}
werror=-DSAFEGI_WERROR=${SAFEGI_WERROR:-OFF}

# The Release pass with CMake's default generator (Unix Makefiles: what a user
# types, and stricter than Ninja about output folders), the sanitizer pass with Ninja.
SAFEGI_GENERATOR=${SAFEGI_GENERATOR:-default} "$root/scripts/build.sh" "$root/build" -DCMAKE_BUILD_TYPE=Release "$werror"
(cd "$root/build" && ctest --output-on-failure -j "$jobs")

if ((sanitize)); then
  # The compiler, the typed library and the renderer core under ASan+UBSan;
  # the GL parts are left out (Mesa's llvmpipe is not built with sanitizers),
  # and so are the renderer's programs and their unchecked and double
  # libraries (no sanitize-labelled test runs them; the Release pass does).
  # -O1 -g1, ASan's recommendation: compiles about 2.5x faster than -O2 -g
  # (the pass's largest cost in CI) and keeps file:line in its reports.
  # Clang, with libFuzzer's coverage instrumentation (-fsanitize=fuzzer-no-link):
  # the same objects then link the fuzz targets (scripts/fuzz.sh reuses this
  # folder when SAFEGI_FUZZ_BUILD_DIR names it, as CI does), so the pipeline is
  # compiled twice in CI, not three times; clang also compiles this pass about
  # 25 % faster than GCC. The Release pass stays GCC, so both compilers build it.
  SAFEGI_GENERATOR=Ninja "$root/scripts/build.sh" "$root/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSAFEGI_SANITIZE=ON "$werror" \
      -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
      "-DCMAKE_CXX_FLAGS=-fsanitize=fuzzer-no-link" -DSAFEGI_FUZZ=ON \
      "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
      -DSAFEGI_BUILD_GL=OFF -DSAFEGI_BUILD_BENCH=OFF -DSAFEGI_BUILD_RENDERER_PROGRAMS=OFF
  (cd "$root/build-asan" && ctest --output-on-failure -j "$jobs" -L sanitize --no-tests=error)
fi
