#!/usr/bin/env bash
# GL preview benchmark (by hand, never a test): frame rate of the Cornell box
# with one point light and its cube shadow map at 512x512, cost per area-light
# sample and per motion-blur time sample, and time from program start to the
# first frame (shader compilation through safegi::compile included).
#   bench/preview/run_preview_bench.sh [build-dir]    (SAFEGI_GL_PLATFORM picks the GL platform)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
preview=$build/bin/safegi-preview
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
scenes=$root/examples/scenes
point_scene=$root/preview/scenes/cornell-point-light.json

echo "# machine: $(nproc) cores; load before: $(cut -d' ' -f1-3 /proc/loadavg)"

run() {  # label, then safegi-preview arguments; prints the --stats lines
  echo "## $1"; shift
  "$preview" "$@" -o "$out/frame.exr" --stats 2>&1 | sed 's/^/   /'
}

run "Cornell box, 1 point light + 6x512^2 shadow map (cached: nothing moves), 512x512" \
    "$point_scene" --resolution 512x512 --frames 120
run "the same, shadow map redrawn every frame" \
    "$point_scene" --resolution 512x512 --frames 60 --refresh-shadows
for n in 1 8 32; do
  run "Cornell box area light, $n samples (5 faces of 256^2 shadow map each), 512x512" \
      "$scenes/cornell-box/cornell-box.json" --resolution 512x512 --light-samples $n --frames 9
done
for n in 1 8 32; do
  run "Cornell box area light, $n samples without area shadows, 512x512" \
      "$scenes/cornell-box/cornell-box.json" --resolution 512x512 --light-samples $n --no-area-shadows --frames 9
done
for t in 1 4 16; do
  run "motion blur, $t time samples x 4 area samples, 512x384" \
      "$scenes/motion-blur.json" --resolution 512x384 --light-samples 4 --time-samples $t --frames 5
done
echo "## start to first frame (process wall clock, point-light Cornell box 512x512, one frame)"
for i in 1 2 3; do
  /usr/bin/time -f "   %e s wall" "$preview" "$point_scene" --resolution 512x512 -o "$out/first.exr" 2>&1 | tail -1
done
echo "# load after: $(cut -d' ' -f1-3 /proc/loadavg)"
