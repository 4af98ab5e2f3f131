#!/usr/bin/env bash
# Configures and builds SafeGI.   usage: [SAFEGI_GENERATOR=Ninja|default|NAME] scripts/build.sh [build-dir] [extra cmake args...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
shift || true
jobs=${SAFEGI_JOBS:-$(nproc)}
# SAFEGI_GENERATOR: Ninja unless set; "default" is CMake's own default (Unix
# Makefiles, what a user types). A folder already configured keeps its generator.
generator=(-G "${SAFEGI_GENERATOR:-Ninja}")
if [[ "${SAFEGI_GENERATOR:-}" == default || -f "$build/CMakeCache.txt" ]]; then generator=(); fi
cmake -S "$root" -B "$build" "${generator[@]}" "$@" >/dev/null
cmake --build "$build" -j "$jobs"
