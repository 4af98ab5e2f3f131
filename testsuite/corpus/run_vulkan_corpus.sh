#!/usr/bin/env bash
# Measures safeglslc on real Vulkan GLSL (docs/frontend-corpus.md, "Vulkan
# shader collections").
#
#   testsuite/corpus/run_vulkan_corpus.sh [--build DIR] [--keep DIR] GIT_DIR[:SUBDIR]...
#
# Each GIT_DIR is a git directory (bare or not) of a snapshot of a public
# repository; SUBDIR limits the extraction to one folder of it. Nothing is
# committed: the trees are extracted to a temporary folder (headers included,
# so `#include` resolves). Selection: every file named by a stage extension
# (.vert … .comp, .rgen .rint .rahit .rchit .rmiss .rcall .mesh .task) that
# `glslangValidator -V --target-env vulkan1.2` accepts. For each selected
# shader: safeglslc with the same flags must succeed (compiled), its module
# must pass spirv-val for vulkan1.2 (re-validated) and equal glslangValidator's
# byte for byte (identical), and its symbol table must give the module's
# sets, bindings, offsets, strides and specialization-constant ids
# (check_vulkan_layout.py). A crash is an exit status above 2, a hang 20 s.
# SAFEGI_VULKAN_CORPUS_VERBOSE=1 prints safeglslc's first error per failure.
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$root/build
keep=
while [[ $# -gt 0 && $1 == --* ]]; do
  case $1 in
    --build) build=$2; shift 2 ;;
    --keep) keep=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
[[ $# -gt 0 ]] || { echo "usage: $0 [--build DIR] [--keep DIR] GIT_DIR[:SUBDIR]..." >&2; exit 2; }
safeglslc=$build/bin/safeglslc
tmp=${keep:-$(mktemp -d)}
[[ -n $keep ]] || trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp"
stages='vert|tesc|tese|geom|frag|comp|rgen|rint|rahit|rchit|rmiss|rcall|mesh|task'

: > "$tmp/selected.list"
for spec in "$@"; do
  git_dir=${spec%%:*}
  sub=; [[ $spec == *:* ]] && sub=${spec#*:}
  name=$(basename "$(cd "$git_dir" && git rev-parse --absolute-git-dir 2>/dev/null | sed 's#/repo$##;s#/\.git$##')")
  dest=$tmp/$name
  mkdir -p "$dest"
  # Blob by blob: large files of a snapshot may be absent (git archive would stop at the first).
  git --git-dir="$git_dir" ls-tree -r HEAD --name-only ${sub:+"$sub"} |
    grep -E "\.($stages|glsl|h|hlsli|inc)$" | while read -r f; do
      mkdir -p "$dest/$(dirname "$f")"
      git --git-dir="$git_dir" show "HEAD:$f" > "$dest/$f" 2>/dev/null || rm -f "$dest/$f"
    done
  echo "corpus $name @ $(git --git-dir="$git_dir" rev-parse --short HEAD)${sub:+ ($sub)}"
  find "$dest" -type f | grep -E "\.($stages)$" | sort | while read -r f; do
    if timeout 20 glslangValidator -V --target-env vulkan1.2 -o "$tmp/ref.spv" "$f" >/dev/null 2>&1; then
      echo "$f" >> "$tmp/selected.list"
    fi
  done
done

total=0 compiled=0 valid=0 identical=0 crashes=0 layouts=0
: > "$tmp/failures.txt"
: > "$tmp/layout-failures.txt"
while read -r f; do
  total=$((total + 1))
  glslangValidator -V --target-env vulkan1.2 -o "$tmp/ref.spv" "$f" >/dev/null 2>&1
  timeout 20 "$safeglslc" -V --target-env vulkan1.2 -o "$tmp/ours.spv" --symbols "$tmp/ours.json" "$f" \
      2> "$tmp/err.txt" >/dev/null
  rc=$?
  if [[ $rc -eq 0 ]]; then
    compiled=$((compiled + 1))
    spirv-val --target-env vulkan1.2 "$tmp/ours.spv" >/dev/null 2>&1 && valid=$((valid + 1))
    cmp -s "$tmp/ref.spv" "$tmp/ours.spv" && identical=$((identical + 1))
    if python3 "$root/testsuite/corpus/check_vulkan_layout.py" "$tmp/ours.json" "$tmp/ours.spv" > "$tmp/layout.txt"; then
      layouts=$((layouts + 1))
    else
      sed "s#^#${f#$tmp/}: #" "$tmp/layout.txt" >> "$tmp/layout-failures.txt"
    fi
  else
    [[ $rc -gt 2 ]] && crashes=$((crashes + 1))
    echo "${f#$tmp/} (exit $rc): $(grep -m1 -E 'error' "$tmp/err.txt" | sed "s#$tmp/##g")" >> "$tmp/failures.txt"
  fi
done < "$tmp/selected.list"

pct() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f %%", b ? 100 * a / b : 0 }'; }
echo "glslang-accepted shaders: $total"
echo "compiled by safeglslc:    $compiled ($(pct "$compiled" "$total"))"
echo "modules spirv-val accepts: $valid of $compiled"
echo "modules byte-identical to glslangValidator's: $identical of $compiled"
echo "symbol tables whose sets, bindings, offsets, strides and constant ids are the module's: $layouts of $compiled"
echo "crashes or hangs: $crashes"
cat "$tmp/layout-failures.txt"
if [[ ${SAFEGI_VULKAN_CORPUS_VERBOSE:-0} == 1 ]]; then cat "$tmp/failures.txt"; fi
