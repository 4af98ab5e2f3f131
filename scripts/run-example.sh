#!/usr/bin/env bash
# The main job: installs dependencies, builds (Release), compiles the bundled
# annotated shaders with safeglslc, renders the bundled Cornell box with the
# typed path tracer and the GL preview, and writes the images under out/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${SAFEGI_OUT:-$root/out}
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" "$root/build" -DCMAKE_BUILD_TYPE=Release
mkdir -p "$out"
bin="$root/build/bin"

if [[ -x "$bin/safeglslc" ]]; then
  for shader in "$root"/examples/shaders/*.sgl.*; do
    [[ -e "$shader" ]] || continue
    name=$(basename "$shader")
    "$bin/safeglslc" "$shader" -I "$root/examples/shaders" -o "$out/${name/.sgl/}" --symbols "$out/${name/.sgl/}.json"
    echo "compiled $name -> out/${name/.sgl/}"
  done
fi
if [[ -x "$bin/safegi-render" ]]; then
  "$bin/safegi-render" "$root/examples/scenes/cornell-box/cornell-box.json" --spp 64 -o "$out/cornell-box.exr"
  echo "rendered out/cornell-box.exr and out/cornell-box.png"
fi
if [[ -x "$bin/safegi-preview" ]]; then
  "$bin/safegi-preview" "$root/examples/scenes/cornell-box/cornell-box.json" -o "$out/cornell-box-preview.exr"
  echo "previewed out/cornell-box-preview.exr and .png"
fi
echo "outputs in $out"
