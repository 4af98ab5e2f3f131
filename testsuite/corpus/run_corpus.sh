#!/usr/bin/env bash
# Measures the SafeGI front end on external shader corpora (docs/frontend-corpus.md).
#
#   testsuite/corpus/run_corpus.sh GLSLANG_GIT_DIR PIGLIT_GIT_DIR [BUILD_DIR]
#
# GLSLANG_GIT_DIR / PIGLIT_GIT_DIR: git directories (bare or not) of snapshots
# of KhronosGroup/glslang and mesa3d/piglit. Nothing is committed: the shaders
# are extracted to a temporary folder. Non-Vulkan selection: glslang's Test/
# files except spv.*, vk.*, hlsl.*, remap.* and names containing "vulkan";
# then only what glslang itself accepts with default (OpenGL) rules counts.
set -euo pipefail
glslang_git=${1:?glslang git dir}
piglit_git=${2:?piglit git dir}
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${3:-$root/build}
cmake --build "$build" --target safegi_corpus_check >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

mkdir -p "$tmp/glslang" "$tmp/piglit"
git --git-dir="$glslang_git" archive HEAD Test | tar -x -C "$tmp/glslang"
git --git-dir="$piglit_git" archive HEAD tests/spec | tar -x -C "$tmp/piglit"

echo "glslang $(git --git-dir="$glslang_git" rev-parse --short HEAD), piglit $(git --git-dir="$piglit_git" rev-parse --short HEAD)"
find "$tmp/glslang/Test" -maxdepth 1 -type f \
     \( -name '*.vert' -o -name '*.frag' -o -name '*.geom' -o -name '*.comp' -o -name '*.tesc' -o -name '*.tese' \) \
     ! -name 'spv.*' ! -name 'vk.*' ! -name 'hlsl.*' ! -name 'remap.*' ! -iname '*vulkan*' | sort > "$tmp/glslang.list"
"$build/bin/safegi_corpus_check" glslang "@$tmp/glslang.list" | sed "s#$tmp/glslang/##g"
find "$tmp/piglit/tests/spec" -type f \
     \( -name '*.vert' -o -name '*.frag' -o -name '*.geom' -o -name '*.comp' -o -name '*.tesc' -o -name '*.tese' \) | sort > "$tmp/piglit.list"
"$build/bin/safegi_corpus_check" piglit "@$tmp/piglit.list" | sed "s#$tmp/piglit/##g"
