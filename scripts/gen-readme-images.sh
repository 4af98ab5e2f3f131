#!/usr/bin/env bash
# Regenerates the README's pictures: the bundled Cornell box path traced by
# safegi-render and drawn by the GL preview, 256 x 256 each (docs/img/).
#   scripts/gen-readme-images.sh [build-dir]     (default build/; builds the two programs first)
# A few seconds on 2 cores once built. The PNGs are 8-bit sRGB, small enough
# to commit (a few tens of KiB); the path-traced one uses enough samples that
# its noise does not dominate the file.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
scene="$root/examples/scenes/cornell-box/cornell-box.json"
img="$root/docs/img"
cmake --build "$build" --target safegi-render safegi-preview >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/bin/safegi-render" "$scene" --resolution 256x256 --spp 256 --seed 1 -o "$tmp/path.exr" -q
"$build/bin/safegi-preview" "$scene" --resolution 256x256 --platform osmesa -o "$tmp/preview.png"
cp "$tmp/path.png" "$img/readme-cornell-box-path.png"
cp "$tmp/preview.png" "$img/readme-cornell-box-preview.png"
ls -l "$img"/readme-cornell-box-*.png | awk '{ printf "%s %d KiB\n", $NF, ($5 + 1023) / 1024 }'
