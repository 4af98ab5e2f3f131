#!/usr/bin/env bash
# Per-process wall time: `safeglslc <shader>` (check + erase + symbol table)
# beside `glslangValidator <the emitted GLSL>` on every annotated example
# shader, best of N runs of a loop of M processes each, and their ratio.
#
#   bench/compiler/per_process.sh [build-dir] [processes-per-run]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
count=${2:-50}
safeglslc="$build/bin/safeglslc"
validator=$(command -v glslangValidator)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Milliseconds per process: best of 3 runs of `count` sequential processes.
per_process_ms() {
  local best=""
  for _ in 1 2 3; do
    local start end
    start=$(date +%s%N)
    for ((i = 0; i < count; ++i)); do "$@" >/dev/null 2>&1; done
    end=$(date +%s%N)
    local ms
    ms=$(awk -v ns=$((end - start)) -v n="$count" 'BEGIN { printf "%.2f", ns / n / 1e6 }')
    if [[ -z $best ]] || awk -v a="$ms" -v b="$best" 'BEGIN { exit !(a < b) }'; then best=$ms; fi
  done
  echo "$best"
}

printf "%-24s %14s %20s %8s\n" shader "safeglslc ms" "glslangValidator ms" ratio
for shader in "$root"/examples/shaders/*.sgl.*; do
  name=$(basename "$shader")
  stage=${name##*.}
  emitted="$tmp/${name/.sgl/}"
  "$safeglslc" "$shader" -o "$emitted"
  ours=$(per_process_ms "$safeglslc" "$shader" -o "$tmp/out.glsl" --symbols "$tmp/out.json")
  theirs=$(per_process_ms "$validator" -S "$stage" "$emitted")
  ratio=$(awk -v a="$ours" -v b="$theirs" 'BEGIN { printf "%.2f", a / b }')
  printf "%-24s %14s %20s %8s\n" "$name" "$ours" "$theirs" "$ratio"
done
