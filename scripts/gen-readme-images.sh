#!/usr/bin/env bash
# Regenerates the README's pictures: the bundled Cornell box path traced by
# safegi-render (256 samples per pixel) and drawn by the GL preview, 128 x 128
# each (docs/img/; the README shows them at twice that).
#   scripts/gen-readme-images.sh [build-dir]     (default build/; builds the two programs first)
# About 8 s of CPU once built (4 s on an idle 2-core machine). Path-traced
# noise is what makes a PNG big: at 256 x 256 even 1024 samples per pixel
# (two minutes of CPU) give 65 KiB; this one is about 23 KiB.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
scene="$root/examples/scenes/cornell-box/cornell-box.json"
img="$root/docs/img"
cmake --build "$build" --target safegi-render safegi-preview >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/bin/safegi-render" "$scene" --resolution 128x128 --spp 256 --seed 1 -o "$tmp/path.exr" -q
"$build/bin/safegi-preview" "$scene" --resolution 128x128 --platform osmesa -o "$tmp/preview.png"
cp "$tmp/path.png" "$img/readme-cornell-box-path.png"
cp "$tmp/preview.png" "$img/readme-cornell-box-preview.png"
ls -l "$img"/readme-cornell-box-*.png | awk '{ printf "%s %d KiB\n", $NF, ($5 + 1023) / 1024 }'
