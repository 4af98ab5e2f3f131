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
# Shaders are selected and checked one per core (SAFEGI_JOBS to change it).
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

: > "$tmp/candidates.list"
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
  find "$dest" -type f | grep -E "\.($stages)$" | sort >> "$tmp/candidates.list"
done

# One worker per core; each file writes only its own results (the lists are sorted after).
jobs=${SAFEGI_JOBS:-$(nproc)}
select_one() {  # select_one FILE: glslangValidator accepts it; its module, FILE.ref.spv, is the reference
  timeout 20 glslangValidator -V --target-env vulkan1.2 -o "$1.ref.spv" "$1" >/dev/null 2>&1 && echo "$1"
}
export -f select_one
xargs -d '\n' -P "$jobs" -I{} bash -c 'select_one "$1"' _ {} < "$tmp/candidates.list" | sort > "$tmp/selected.list"

# Per shader one line "VERDICTS<TAB>file" (compiled, valid, identical, layout: 1 or 0; crash),
# a first error for a failure and the layout mismatches, each in files of its own.
check_one() {  # check_one FILE
  local f=$1 work rc
  work=$(mktemp -d "$tmp/work.XXXXXX")
  timeout 20 "$safeglslc" -V --target-env vulkan1.2 -o "$work/ours.spv" --symbols "$work/ours.json" "$f" \
      2> "$work/err.txt" >/dev/null
  rc=$?
  if [[ $rc -eq 0 ]]; then
    local valid=0 identical=0 layout=0
    spirv-val --target-env vulkan1.2 "$work/ours.spv" >/dev/null 2>&1 && valid=1
    cmp -s "$f.ref.spv" "$work/ours.spv" && identical=1
    if python3 "$root/testsuite/corpus/check_vulkan_layout.py" "$work/ours.json" "$work/ours.spv" > "$work/layout.txt"; then
      layout=1
    else
      sed "s#^#${f#$tmp/}: #" "$work/layout.txt" > "$work.layout"
    fi
    printf '1 %d %d %d 0\t%s\n' "$valid" "$identical" "$layout" "$f"
  else
    local crash=0
    [[ $rc -gt 2 ]] && crash=1
    echo "${f#$tmp/} (exit $rc): $(grep -m1 -E 'error' "$work/err.txt" | sed "s#$tmp/##g")" > "$work.failure"
    printf '0 0 0 0 %d\t%s\n' "$crash" "$f"
  fi
  rm -rf "$work"
}
export -f check_one
export tmp root safeglslc
xargs -d '\n' -P "$jobs" -I{} bash -c 'check_one "$1"' _ {} < "$tmp/selected.list" > "$tmp/verdicts.txt"
cat "$tmp"/work.*.failure 2>/dev/null | sort > "$tmp/failures.txt"
cat "$tmp"/work.*.layout 2>/dev/null | sort > "$tmp/layout-failures.txt"
rm -f "$tmp"/work.*.failure "$tmp"/work.*.layout
read -r total compiled valid identical layouts crashes < <(awk -F'\t' '{ split($1, v, " ");
  n++; c += v[1]; va += v[2]; id += v[3]; l += v[4]; cr += v[5] } END { print n + 0, c + 0, va + 0, id + 0, l + 0, cr + 0 }' "$tmp/verdicts.txt")

pct() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f %%", b ? 100 * a / b : 0 }'; }
echo "glslang-accepted shaders: $total"
echo "compiled by safeglslc:    $compiled ($(pct "$compiled" "$total"))"
echo "modules spirv-val accepts: $valid of $compiled"
echo "modules byte-identical to glslangValidator's: $identical of $compiled"
echo "symbol tables whose sets, bindings, offsets, strides and constant ids are the module's: $layouts of $compiled"
echo "crashes or hangs: $crashes"
cat "$tmp/layout-failures.txt"
if [[ ${SAFEGI_VULKAN_CORPUS_VERBOSE:-0} == 1 ]]; then cat "$tmp/failures.txt"; fi
